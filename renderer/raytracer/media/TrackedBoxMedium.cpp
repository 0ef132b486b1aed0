#include "media/TrackedBoxMedium.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

// The null-collision coefficient: what the majorant adds to the real one (never below zero).
Vec3f nullCoefficient(float majorant, Vec3f sigmaA, Vec3f sigmaS) {
    const Vec3f n = Vec3f{majorant, majorant, majorant} - sigmaA - sigmaS;
    return {std::max(0.0f, n.x), std::max(0.0f, n.y), std::max(0.0f, n.z)};
}

// Ratio tracking's product falls geometrically; below this a coin toss ends it (unbiased).
constexpr float kRouletteBelow = 0.05f;

}  // namespace

TrackedBoxMedium::TrackedBoxMedium(const Transform& boxToWorld, MajorantGrid majorants, HenyeyGreenstein phase)
    : ParticipatingMedium(phase), worldToBox_(inverse(boxToWorld)), majorants_(std::move(majorants)) {}

bool TrackedBoxMedium::clip(Vec3f o, Vec3f d, float tMax, Vec3f& oBox, Vec3f& dBox, float& t0, float& t1) const {
    oBox = transformPoint(worldToBox_, o);
    dBox = transformVector(worldToBox_, d);
    t0 = 0;
    t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const float inv = 1 / dBox[axis];  // infinite for a ray parallel to the slab: the compare still works
        float tNear = -oBox[axis] * inv, tFar = (1 - oBox[axis]) * inv;
        if (tNear > tFar) std::swap(tNear, tFar);
        if (std::isnan(tNear) || std::isnan(tFar)) return false;  // parallel on the slab's plane
        t0 = std::max(t0, tNear);
        t1 = std::min(t1, tFar);
    }
    return t0 < t1;
}

template <class Collide>
void TrackedBoxMedium::walkCollisions(Vec3f oBox, Vec3f dBox, float t0, float t1, Pcg32& rng, Collide collide) const {
    walkMajorants(majorants_, oBox, dBox, t0, t1, [&](float t, float tEnd, float majorant) {
        if (majorant <= 0) return true;
        for (;;) {
            t += rng.exponential() / majorant;
            if (t >= tEnd) return true;
            Vec3f sigmaA, sigmaS;
            coefficients(oBox + t * dBox, sigmaA, sigmaS);
            if (!collide(t, sigmaA, sigmaS, majorant)) return false;
        }
    });
}

MediumEvent TrackedBoxMedium::sample(Vec3f o, Vec3f d, float tMax, int hero, Pcg32& rng) const {
    MediumEvent e;
    e.t = tMax;
    Vec3f oBox, dBox;
    float t0, t1;
    if (!clip(o, d, tMax, oBox, dBox, t0, t1)) return e;
    // Each tentative collision (at the majorant rate, the same for every channel) is absorption,
    // scattering or a null collision with the hero's coefficients over the majorant as
    // probabilities. A channel's density of the same choice is its own coefficient over the
    // majorant, so weight and ratio are both coefficient over the hero's (1 in a grey medium:
    // plain delta tracking).
    walkCollisions(oBox, dBox, t0, t1, rng, [&](float t, Vec3f sigmaA, Vec3f sigmaS, float majorant) {
        const Vec3f sigmaN = nullCoefficient(majorant, sigmaA, sigmaS);
        const float u = rng.uniform() * majorant;
        if (u < sigmaA[hero]) {
            e.weight = {};
            return false;
        }
        const bool scatters = u < sigmaA[hero] + sigmaS[hero];
        const Vec3f sigma = scatters ? sigmaS : sigmaN;
        e.weight *= sigma / sigma[hero];
        e.pdfRatio *= sigma / sigma[hero];
        if (!scatters) return true;
        e.scattered = true;
        e.t = t;
        return false;
    });
    return e;
}

Vec3f TrackedBoxMedium::transmittance(Vec3f o, Vec3f d, float tMax, Pcg32& rng) const {
    Vec3f oBox, dBox, tr{1, 1, 1};
    float t0, t1;
    if (!clip(o, d, tMax, oBox, dBox, t0, t1)) return tr;
    walkCollisions(oBox, dBox, t0, t1, rng, [&](float, Vec3f sigmaA, Vec3f sigmaS, float majorant) {
        tr *= nullCoefficient(majorant, sigmaA, sigmaS) / majorant;
        if (maxComponent(tr) >= kRouletteBelow) return true;
        if (rng.uniform() < 0.5f) {
            tr = {};
            return false;
        }
        tr = 2.0f * tr;
        return true;
    });
    return tr;
}

}  // namespace lenslab
