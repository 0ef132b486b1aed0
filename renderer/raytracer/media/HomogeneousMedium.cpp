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

// A walk's channel probabilities: in proportion to the throughput.
Vec3f byThroughput(Vec3f throughput) {
    const float total = throughput.x + throughput.y + throughput.z;
    return total > 0 ? throughput / total : Vec3f{1.0f / 3, 1.0f / 3, 1.0f / 3};
}

}  // namespace

float HomogeneousMedium::distance(int channel, Pcg32& rng) const {
    const float sigma = sigmaT_[channel];
    return sigma > 0 ? rng.exponential() / sigma : std::numeric_limits<float>::infinity();
}

MediumEvent HomogeneousMedium::eventAt(float t, float tMax, Vec3f& pdf) const {
    // Scattered at t (density sigma_t T(t)) or passed on to tMax (T(tMax)), the same for every
    // channel's draw: pdf receives each channel's density of the event.
    MediumEvent e;
    e.scattered = t < tMax;
    e.t = e.scattered ? t : tMax;
    const Vec3f tr = beer(sigmaT_, e.t);
    pdf = e.scattered ? sigmaT_ * tr : tr;
    e.weight = e.scattered ? sigmaS_ * tr : tr;  // f, divided by the caller's density
    return e;
}

MediumEvent HomogeneousMedium::sample(Vec3f, Vec3f, float tMax, int hero, Pcg32& rng) const {
    if (isBlack(sigmaS_)) return absorbed(tMax);
    Vec3f pdf;
    MediumEvent e = eventAt(distance(hero, rng), tMax, pdf);
    const float heroPdf = pdf[hero];
    if (!(heroPdf > 0)) return {false, e.t, {}, {1, 1, 1}};
    e.weight = e.weight / heroPdf;
    e.pdfRatio = pdf / heroPdf;
    return e;
}

float HomogeneousMedium::walkDistance(Vec3f throughput, Pcg32& rng) const {
    if (isBlack(sigmaS_)) return std::numeric_limits<float>::infinity();
    const Vec3f w = byThroughput(throughput);
    const float u = rng.uniform();
    return distance(u < w.x ? 0 : u < w.x + w.y ? 1 : 2, rng);
}

MediumEvent HomogeneousMedium::walkEvent(float t, float tMax, Vec3f throughput) const {
    if (isBlack(sigmaS_)) return absorbed(tMax);
    Vec3f pdf;
    MediumEvent e = eventAt(t, tMax, pdf);
    const float mixture = dot(byThroughput(throughput), pdf);
    if (!(mixture > 0)) return {false, e.t, {}, {1, 1, 1}};
    e.weight = e.weight / mixture;
    return e;
}

MediumEvent HomogeneousMedium::absorbed(float tMax) const {
    // A pure absorber: the transmittance itself, without sampling noise.
    MediumEvent e;
    e.t = tMax;
    e.weight = beer(sigmaT_, tMax);
    return e;
}

Vec3f HomogeneousMedium::transmittance(Vec3f, Vec3f, float tMax, Pcg32&) const { return beer(sigmaT_, tMax); }

}  // namespace lenslab
