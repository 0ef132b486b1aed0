#pragma once
// The scene's geometry in Embree 3: the world's shapes in one scene, every instanced object in a
// scene of its own that each ObjectInstance places with an Embree instance (one copy of the object
// however many instances). Answers closest-hit and shadow queries and turns hits into world-space
// shading records.
#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "Light.h"
#include "Material.h"
#include "SceneDescription.h"

namespace lenslab {

struct Intersection {
    SurfaceHit hit;
    float t = 0;
    const Material* material = nullptr;
    const Light* light = nullptr;  // the area light when the surface emits
};

class SceneGeometry {
public:
    // Takes the shapes, objects, instances and lights from the scene, creates an area light for every
    // primitive of an emitting world shape, and tells every light the scene's bounding sphere.
    explicit SceneGeometry(SceneDescription& scene);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    bool intersect(Vec3f origin, Vec3f direction, float tMax, Intersection& out) const;
    bool occluded(Vec3f origin, Vec3f direction, float tMax) const;
    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }

private:
    // What one Embree geometry id of the world scene stands for: a shape (with the index of its
    // first primitive's area light, when it emits) or an instance.
    struct WorldSlot {
        const ShapeEntry* shape = nullptr;
        std::size_t firstLight = 0;
        bool emits = false;
        const ObjectInstance* instance = nullptr;
    };
    struct ObjectScene {
        RTCScene scene = nullptr;
        std::vector<const ShapeEntry*> shapes;  // by Embree geometry id
    };

    ObjectScene buildObject(const ObjectDefinition& object);

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<ShapeEntry> shapes_;
    std::vector<ObjectDefinition> objects_;
    std::vector<ObjectInstance> instances_;
    std::vector<WorldSlot> world_;         // by Embree geometry id
    std::vector<ObjectScene> objectScenes_;  // by object index
    std::vector<std::unique_ptr<Light>> lights_;
};

}  // namespace lenslab
