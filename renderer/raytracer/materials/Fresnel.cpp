#include "materials/Fresnel.h"

#include <cmath>
#include <utility>

namespace lenslab {

namespace {

Vec3f sqrt3(Vec3f v) { return {std::sqrt(v.x), std::sqrt(v.y), std::sqrt(v.z)}; }
Vec3f div3(Vec3f a, Vec3f b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }

}  // namespace

float fresnelDielectric(float cosI, float etaI, float etaT) {
    cosI = std::clamp(cosI, -1.0f, 1.0f);
    if (cosI < 0) {
        std::swap(etaI, etaT);
        cosI = -cosI;
    }
    const float sinT = etaI / etaT * std::sqrt(std::max(0.0f, 1.0f - cosI * cosI));
    if (sinT >= 1.0f) return 1.0f;  // total internal reflection
    const float cosT = std::sqrt(std::max(0.0f, 1.0f - sinT * sinT));
    const float par = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
    const float perp = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
    return 0.5f * (par * par + perp * perp);
}

// The exact conductor equations in the form that avoids complex arithmetic (as in pbrt-v3, after
// S. Lagarde, "Memo on Fresnel equations", 2013): a^2 + b^2 and a from the relative index.
Vec3f fresnelConductor(float cosI, float etaI, Vec3f eta, Vec3f k) {
    cosI = std::min(std::fabs(cosI), 1.0f);
    const Vec3f n = eta / etaI, nk = k / etaI;
    const float cos2 = cosI * cosI, sin2 = 1.0f - cos2;
    const Vec3f n2 = n * n, nk2 = nk * nk;
    const Vec3f t0 = n2 - nk2 - Vec3f{sin2, sin2, sin2};
    const Vec3f a2b2 = sqrt3(t0 * t0 + 4.0f * n2 * nk2);
    const Vec3f t1 = a2b2 + Vec3f{cos2, cos2, cos2};
    const Vec3f a = sqrt3(0.5f * (a2b2 + t0));
    const Vec3f t2 = 2.0f * cosI * a;
    const Vec3f rs = div3(t1 - t2, t1 + t2);
    const Vec3f t3 = cos2 * a2b2 + Vec3f{sin2 * sin2, sin2 * sin2, sin2 * sin2};
    const Vec3f t4 = sin2 * t2;
    const Vec3f rp = rs * div3(t3 - t4, t3 + t4);
    return 0.5f * (rp + rs);
}

Vec3f fresnelSchlick(float cosI, Vec3f r0) {
    const float m = 1.0f - cosI, m5 = (m * m) * (m * m) * m;
    return r0 + m5 * (Vec3f{1, 1, 1} - r0);
}

Vec3f Fresnel::evaluate(float cosI) const {
    switch (kind) {
        case Kind::Dielectric: {
            const float f = fresnelDielectric(cosI, etaI, etaT);
            return {f, f, f};
        }
        case Kind::Coat: {
            const float f = fresnelDielectric(std::fabs(cosI), etaI, etaT);
            return {f, f, f};
        }
        case Kind::Conductor: return fresnelConductor(cosI, etaI, eta, k);
        case Kind::One: break;
    }
    return {1, 1, 1};
}

}  // namespace lenslab
