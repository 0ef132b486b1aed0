#pragma once
// Fresnel reflectance of unpolarised light at a smooth interface, as pbrt-v3 defines it.
#include "core/Vec3f.h"

namespace lenslab {

// Between two dielectrics. cosI is signed against the surface normal: positive means the light
// arrives from the etaI side; negative swaps the media (light arrives from inside).
float fresnelDielectric(float cosI, float etaI, float etaT);

// From a dielectric (index etaI) onto a conductor of complex index eta + i k, per RGB channel.
// Only |cosI| matters: the conductor absorbs whatever enters it.
Vec3f fresnelConductor(float cosI, float etaI, Vec3f eta, Vec3f k);

// Schlick's approximation with reflectance r0 at normal incidence.
Vec3f fresnelSchlick(float cosI, Vec3f r0);

// The Fresnel factor a microfacet reflection lobe applies: none (1), dielectric, a two-sided
// dielectric coat, or conductor.
struct Fresnel {
    enum class Kind { One, Dielectric, Coat, Conductor } kind = Kind::One;
    float etaI = 1, etaT = 1;  // dielectric, coat
    Vec3f eta, k;              // conductor (seen from a medium of index etaI)

    static Fresnel one() { return {}; }
    static Fresnel dielectric(float etaI, float etaT) { return {Kind::Dielectric, etaI, etaT, {}, {}}; }
    // pbrt-v4's coateddiffuse and coatedconductor are two-sided: seen from behind the shading
    // normal they reflect as from the front (etaI's side), never totally as glass seen from inside.
    static Fresnel coat(float etaI, float etaT) { return {Kind::Coat, etaI, etaT, {}, {}}; }
    static Fresnel conductor(Vec3f eta, Vec3f k) { return {Kind::Conductor, 1, 1, eta, k}; }
    Vec3f evaluate(float cosI) const;
};

}  // namespace lenslab
