#include "media/HenyeyGreenstein.h"

#include <cmath>

namespace lenslab {

namespace {

constexpr float kInv4Pi = 0.0795774715f;

}  // namespace

float HenyeyGreenstein::evaluate(Vec3f d, Vec3f wi) const {
    const float cosTheta = dot(d, wi);
    const float denom = 1 + g_ * g_ - 2 * g_ * cosTheta;
    return kInv4Pi * (1 - g_ * g_) / (denom * std::sqrt(denom));
}

Vec3f HenyeyGreenstein::sample(Vec3f d, float u1, float u2) const {
    float cosTheta;
    if (std::fabs(g_) < 1e-3f) {
        cosTheta = 1 - 2 * u1;  // isotropic: the closed form below divides by g
    } else {
        const float s = (1 - g_ * g_) / (1 - g_ + 2 * g_ * u1);
        cosTheta = (1 + g_ * g_ - s * s) / (2 * g_);
    }
    cosTheta = std::clamp(cosTheta, -1.0f, 1.0f);
    const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
    const float phi = 2 * float(M_PI) * u2;
    return Frame(d).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
}

}  // namespace lenslab
