#pragma once
// Participating media: volumes that absorb and scatter light (fog, smoke, clouds). Coefficients
// are RGB per metre of world space; each colour channel is its own spectrally constant medium.
//
// One path carries all three channels (no per-channel colour noise). Distances are drawn for a hero
// channel chosen once per path, and the path is weighted by one-sample MIS over the three channels
// as heroes (pbrt-v4's spectral MIS, here over RGB): each event reports, besides its weight
// f / p_hero, the ratio p_c / p_hero of every channel's sampling density to the hero's, and the
// integrator divides the throughput by the mean ratio over the path. A path's weight per channel
// thus stays below 3 times what that channel sampled alone would give, however many events.
// Grids add null collisions against one majorant.
#include <memory>
#include <string>
#include <vector>

#include "core/ParamSet.h"
#include "core/Transform.h"
#include "media/HenyeyGreenstein.h"
#include "sampling/Sampling.h"

namespace lenslab {

// What happened to a ray crossing a medium up to tMax: scattered at t, or passed on to tMax.
// weight: f / p_hero per channel (transmittance and coefficients over the hero's sampling
// density); black means the path ends (absorbed). pdfRatio: p_c / p_hero per channel.
struct MediumEvent {
    bool scattered = false;
    float t = 0;
    Vec3f weight{1, 1, 1}, pdfRatio{1, 1, 1};
};

class ParticipatingMedium {
public:
    explicit ParticipatingMedium(HenyeyGreenstein phase) : phase_(phase) {}
    virtual ~ParticipatingMedium() = default;
    // d unit length, so t is a distance in metres; tMax may be infinite. hero: 0, 1 or 2.
    virtual MediumEvent sample(Vec3f o, Vec3f d, float tMax, int hero, Pcg32& rng) const = 0;
    // An unbiased estimate of the transmittance from o to o + tMax d, per channel.
    virtual Vec3f transmittance(Vec3f o, Vec3f d, float tMax, Pcg32& rng) const = 0;
    const HenyeyGreenstein& phase() const { return phase_; }

private:
    HenyeyGreenstein phase_;
};

// The media on the two sides of a surface (pbrt's MediumInterface "inside" "outside"): inside lies
// against the surface's oriented normal. Null is vacuum. Equal sides are no boundary: a ray
// crossing keeps the medium it travels in.
struct MediumInterface {
    std::shared_ptr<const ParticipatingMedium> inside, outside;
    bool isTransition() const { return inside != outside; }
    // The medium a ray enters leaving the surface along w (ng the geometric normal).
    const ParticipatingMedium* leaving(Vec3f w, Vec3f ng) const { return dot(w, ng) > 0 ? outside.get() : inside.get(); }
};

// MakeNamedMedium's "string type": pbrt-v3's homogeneous and heterogeneous, pbrt-v4's homogeneous,
// uniformgrid, cloud and nanovdb; mediumToWorld is the current transform there, resolve finds a
// nanovdb medium's file. Anything else is a SceneError naming the line.
std::shared_ptr<const ParticipatingMedium> makeMedium(const std::string& type, const ParamSet& params,
                                         const Transform& mediumToWorld, const PathResolver& resolve,
                                         std::vector<std::string>& warnings);

}  // namespace lenslab
