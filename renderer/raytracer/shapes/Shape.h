#pragma once
// A surface the ray tracer can hit: triangle meshes and pbrt-v3's quadrics (sphere, disk,
// cylinder, cone, paraboloid, hyperboloid). A shape lives in the space of the group that holds it
// (the world, or an object's own space for ObjectBegin/ObjectInstance) and is one Embree geometry
// there. Area lights sample it by area, one light per primitive (a triangle, or the whole quadric).
#include <embree3/rtcore.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "materials/Material.h"
#include "core/ParamSet.h"
#include "core/Transform.h"

namespace lenslab {

// A point drawn on a primitive, in the shape's space.
// A whole sphere in the group's space, for Embree's own sphere primitive.
struct EmbreeSphere {
    Vec3f centre;
    float radius = 0;
};

struct ShapeSample {
    Vec3f p;
    Vec3f n;          // oriented geometric normal (the side ReverseOrientation chose), unit
    float pdf = 0;    // per unit area
};

class Shape {
public:
    virtual ~Shape() = default;
    // Adds this shape to `scene` as one geometry; returns Embree's geometry id. The shape must outlive
    // the scene (user geometries keep a pointer to it).
    virtual unsigned attach(RTCDevice device, RTCScene scene) const = 0;
    // Set for a whole sphere under a similarity: many of those are traced fastest as one batch of
    // Embree's sphere primitive (one geometry each would cost Embree a lookup per primitive test);
    // the batch calls surface() with primitive 0.
    virtual std::optional<EmbreeSphere> embreeSphere() const { return std::nullopt; }
    // The surface record at a hit of ray (o, d) at distance t on primitive `prim`, with Embree's hit
    // (u, v) (barycentrics for triangles; unused for quadrics), in the shape's space: position,
    // oriented geometric normal, shading normal, pbrt-v3's (u, v).
    virtual void surface(Vec3f o, Vec3f d, float t, unsigned prim, float hitU, float hitV, SurfaceHit& out) const = 0;
    // Emitters: primitives that carry their own light, the area of each, a point drawn on one, and
    // the density of that draw per unit area at a point `at` of the primitive.
    virtual std::size_t primitiveCount() const = 0;
    virtual float primitiveArea(std::size_t prim) const = 0;
    virtual ShapeSample samplePrimitive(std::size_t prim, float u1, float u2) const = 0;
    virtual float primitivePdf(std::size_t prim, const SurfaceHit& at) const = 0;
};

// Shape "TYPE" params under the transform objectToGroup (the current transform; the space of the
// enclosing ObjectBegin for instanced objects, else world). reverseOrientation is the graphics
// state's flag; `textures` the float textures an "alpha" cutout may name. Throws SceneError naming
// the parameter for bad input; unknown types are an error.
std::vector<std::shared_ptr<const Shape>> makeShapes(const std::string& type, const ParamSet& params,
                                                     const Transform& objectToGroup, bool reverseOrientation,
                                                     const TextureMap& textures, const PathResolver& resolve,
                                                     std::vector<std::string>& warnings);

}  // namespace lenslab
