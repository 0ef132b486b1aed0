#pragma once
// The world's geometry in Embree 3: triangle meshes, and spheres as Embree's analytic sphere
// primitive. Answers closest-hit and shadow queries and turns hits into shading records.
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
    // Takes the shapes from the scene and creates an area light for every emitting triangle or
    // sphere; lights() holds those and the scene's other lights.
    explicit SceneGeometry(SceneDescription& scene);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    bool intersect(Vec3f origin, Vec3f direction, float tMax, Intersection& out) const;
    bool occluded(Vec3f origin, Vec3f direction, float tMax) const;
    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }

private:
    struct MeshRecord {
        TriangleMesh mesh;
        std::vector<const Light*> triangleLights;  // per triangle, when the mesh emits
    };
    struct SphereRecord {
        Sphere sphere;
        const Light* light = nullptr;
    };

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<MeshRecord> meshes_;      // by Embree geometry id
    std::vector<SphereRecord> spheres_;   // by primitive id of the one sphere geometry
    unsigned sphereGeometry_ = RTC_INVALID_GEOMETRY_ID;
    std::vector<std::unique_ptr<Light>> lights_;
};

}  // namespace lenslab
