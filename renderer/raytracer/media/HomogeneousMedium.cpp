#include "media/HomogeneousMedium.h"

#include <cmath>
#include <limits>

namespace lenslab {

namespace {

// exp(-sigma t) per channel, with 0 * infinity (a clear channel over an endless ray) as no loss.
Vec3f beer(Vec3f sigma, float t) {
    const auto one = [t](float s) { return s == 0 ? 1.0f : std::exp(-s * t); };
    return {one(sigma.x), one(sigma.y), one(sigma.z)};
}

}  // namespace

MediumEvent HomogeneousMedium::sample(Vec3f, Vec3f, float tMax, int hero, Pcg32& rng) const {
    MediumEvent e;
    if (isBlack(sigmaS_)) {  // a pure absorber: the transmittance itself, without sampling noise
        e.t = tMax;
        e.weight = beer(sigmaT_, tMax);
        return e;
    }
    // Distance drawn for the hero channel: density sigma_t T(t) of scattering at t, T(tMax) of
    // passing through.
    const float sigma = sigmaT_[hero];
    const float u = rng.uniform();
    const float t = sigma > 0 ? -std::log1p(-u) / sigma : std::numeric_limits<float>::infinity();
    e.scattered = t < tMax;
    e.t = e.scattered ? t : tMax;
    const Vec3f tr = beer(sigmaT_, e.t);
    const Vec3f pdf = e.scattered ? sigmaT_ * tr : tr;
    const float heroPdf = pdf[hero];
    if (!(heroPdf > 0)) return {false, e.t, {}, {1, 1, 1}};
    e.weight = (e.scattered ? sigmaS_ * tr : tr) / heroPdf;
    e.pdfRatio = pdf / heroPdf;
    return e;
}

Vec3f HomogeneousMedium::transmittance(Vec3f, Vec3f, float tMax, Pcg32&) const { return beer(sigmaT_, tMax); }

}  // namespace lenslab
