#pragma once
// Light transport: the radiance arriving along a camera ray. One implementation per pbrt-v3
// integrator lenslab has: path, directlighting, whitted.
#include <cstdint>
#include <memory>

#include "sampling/Sampling.h"
#include "scene/SceneDescription.h"
#include "geometry/SceneGeometry.h"

namespace lenslab {

class Integrator {
public:
    virtual ~Integrator() = default;
    // Radiance arriving along the ray (world space) at its moment `time` (SceneGeometry's), which
    // every ray of the path shares. raysTraced counts closest-hit and shadow rays.
    virtual Vec3f radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng, std::uint64_t& raysTraced) const = 0;
};

// The geometry (with its lights' scene bounds set) and the camera's medium (null: vacuum; only
// volpath renders media) must outlive the integrator.
std::unique_ptr<Integrator> makeIntegrator(const SceneGeometry& geometry, const IntegratorSpec& spec,
                                           const ParticipatingMedium* cameraMedium);

}  // namespace lenslab
