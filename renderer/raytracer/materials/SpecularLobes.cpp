#include "materials/SpecularLobes.h"

#include <cmath>

namespace lenslab {

namespace {

// Refracts wo through the smooth boundary (normal +z); the radiance scale for the crossing.
bool refractSmooth(Vec3f wo, float etaA, float etaB, Vec3f& wi, float& radianceScale) {
    const bool fromA = wo.z > 0;
    const float etaFrom = fromA ? etaA : etaB, etaTo = fromA ? etaB : etaA;
    if (etaFrom == etaTo) {
        wi = -wo;
    } else if (!refract(wo, {0, 0, fromA ? 1.0f : -1.0f}, etaFrom / etaTo, wi)) {
        return false;
    }
    radianceScale = (etaFrom * etaFrom) / (etaTo * etaTo);
    return true;
}

}  // namespace

bool SpecularReflection::sample(Vec3f wo, float, float, float, LobeSample& s) const {
    s.wi = {-wo.x, -wo.y, wo.z};
    s.pdf = 1;
    s.specular = true;
    s.f = fresnel_.evaluate(s.wi.z) / std::fabs(s.wi.z);
    return true;
}

bool SpecularTransmission::sample(Vec3f wo, float, float, float, LobeSample& s) const {
    float scale = 1;
    if (!refractSmooth(wo, etaA_, etaB_, s.wi, scale)) return false;
    const float transmitted = 1.0f - fresnelDielectric(s.wi.z, etaA_, etaB_);
    s.pdf = 1;
    s.specular = true;
    const float v = transmitted * scale / std::fabs(s.wi.z);
    s.f = {v, v, v};
    return true;
}

bool FresnelSpecular::sample(Vec3f wo, float uc, float, float, LobeSample& s) const {
    const float F = fresnelDielectric(wo.z, etaA_, etaB_);
    s.specular = true;
    if (uc < F) {
        s.wi = {-wo.x, -wo.y, wo.z};
        s.pdf = F;
        s.f = (F / std::fabs(s.wi.z)) * r_;
        return true;
    }
    float scale = 1;
    if (!refractSmooth(wo, etaA_, etaB_, s.wi, scale)) return false;
    s.pdf = 1.0f - F;
    s.f = ((1.0f - F) * scale / std::fabs(s.wi.z)) * t_;
    return true;
}

bool ThinDielectric::sample(Vec3f wo, float uc, float, float, LobeSample& s) const {
    float r = fresnelDielectric(std::fabs(wo.z), 1.0f, eta_);
    const float t = 1 - r;
    if (r < 1) r += t * t * r / (1 - r * r);
    const bool reflect = uc < r;
    s.wi = reflect ? Vec3f{-wo.x, -wo.y, wo.z} : -wo;
    s.pdf = reflect ? r : 1 - r;
    s.specular = true;
    const float v = s.pdf / std::fabs(s.wi.z);
    s.f = {v, v, v};
    return s.pdf > 0;
}

}  // namespace lenslab
