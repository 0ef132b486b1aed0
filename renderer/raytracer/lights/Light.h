#pragma once
// Light sources: point, spot, distant, infinite (constant) and diffuse area emitters on
// shapes (AreaLight.h). Radiometric quantities in the scene's RGB; positions in metres.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "materials/Material.h"
#include "core/ParamSet.h"
#include "core/SceneDialect.h"
#include "core/Transform.h"
#include "core/Vec3f.h"

namespace lenslab {

struct LightSample {
    Vec3f wi;                  // from the shading point toward the light
    float distance = std::numeric_limits<float>::infinity();
    Vec3f radiance;            // arriving at the shading point (unoccluded)
    float pdf = 0;             // solid angle; 1 for delta lights
    bool delta = false;
};

class Light {
public:
    virtual ~Light() = default;
    // Samples light arriving at p; false when none can.
    virtual bool sample(Vec3f p, float u1, float u2, LightSample& s) const = 0;
    // For lights a scattered ray can hit: the solid-angle pdf of sample() at p choosing the
    // direction w, which meets the light at `at` (area lights) or escapes (at == nullptr: infinite).
    virtual float pdf(Vec3f p, Vec3f w, const SurfaceHit* at) const = 0;
    // Radiance leaving the light at `at` toward -w (w the ray direction that hit it), or arriving
    // from the environment along -w for an escaped ray (at == nullptr).
    virtual Vec3f emitted(const SurfaceHit* at, Vec3f w) const = 0;
    virtual bool isInfinite() const { return false; }
    // Lights at a point or from a single direction: no scattered ray can reach them.
    virtual bool isDelta() const { return false; }
    // Emitted power (RGB, W), for choosing lights in proportion to it. Distant and infinite lights
    // need the scene's bounding sphere first.
    virtual Vec3f power() const = 0;
    virtual void setSceneBounds(Vec3f /*centre*/, float /*radius*/) {}
};

// LightSource "TYPE" params, with the current transform: point, spot, distant, infinite (constant or
// with an environment map), goniometric, projection, read as the scene's pbrt version means them.
// `resolve` finds the image files they name.
std::unique_ptr<Light> makeLight(const std::string& type, const ParamSet& params, const Transform& lightToWorld,
                                 SceneDialect dialect, const PathResolver& resolve, std::vector<std::string>& warnings);

}  // namespace lenslab
