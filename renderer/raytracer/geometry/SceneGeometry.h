#pragma once
// The scene's geometry in Embree 3: the world's shapes in one scene, every instanced object in a
// scene of its own that each ObjectInstance places with an Embree instance (one copy of the object
// however many instances). Answers closest-hit and shadow queries and turns hits into world-space
// shading records. Moving instances (and moving shapes, which the parser makes instances) are
// Embree motion-blurred instances: every query is at a moment, a TransformTimes::fraction in [0, 1].
#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "lights/Light.h"
#include "materials/Material.h"
#include "scene/SceneDescription.h"

namespace lenslab {

struct Intersection {
    SurfaceHit hit;  // in world space, the material's bump map applied
    float t = 0;
    float time = 0;  // the query's moment: rays leaving the hit (shadow rays, bounces) keep it
    const Material* material = nullptr;
    const Light* light = nullptr;  // the area light when the surface emits
    const MediumInterface* media = nullptr;  // the media on the surface's two sides
};

class SceneGeometry {
public:
    // Takes the shapes, objects, instances and lights from the scene, creates an area light for every
    // primitive of an emitting world shape, and tells every light the scene's bounding sphere.
    explicit SceneGeometry(SceneDescription& scene);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    bool intersect(Vec3f origin, Vec3f direction, float tMax, float time, Intersection& out) const;
    bool occluded(Vec3f origin, Vec3f direction, float tMax, float time) const;
    // Some shape is only a boundary between media (Material::isPassthrough): a shadow ray must be
    // followed hit by hit. Without one, any hit blocks it and occluded() answers.
    bool hasPassthroughSurfaces() const { return hasPassthrough_; }
    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }

private:
    // One Embree scene: the world or an object. Its geometry ids name shapes, instances (world
    // only) or the one batch of whole spheres, whose primitive ids name shapes in turn.
    struct Group {
        RTCScene scene = nullptr;
        std::vector<const ShapeEntry*> byGeometry;      // nullptr: the sphere batch or an instance
        std::vector<const ObjectInstance*> instances;   // by geometry id; nullptr: not an instance
        unsigned sphereBatch = RTC_INVALID_GEOMETRY_ID;
        std::vector<const ShapeEntry*> spheres;         // by the batch's primitive id
    };

    Group buildGroup(const std::vector<ShapeEntry>& shapes);
    // The shape Embree hit, and its primitive.
    static const ShapeEntry& hitShape(const Group& group, unsigned geomID, unsigned& prim);

    RTCDevice device_ = nullptr;
    std::vector<ShapeEntry> shapes_;
    std::vector<ObjectDefinition> objects_;
    std::vector<ObjectInstance> instances_;
    Group world_;
    std::vector<Group> objectGroups_;          // by object index
    std::vector<std::size_t> firstLight_;      // by world shape: its first primitive's area light
    std::vector<std::unique_ptr<Light>> lights_;
    bool hasPassthrough_ = false;
};

}  // namespace lenslab
