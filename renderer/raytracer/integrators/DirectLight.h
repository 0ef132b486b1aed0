#pragma once
// Direct illumination estimates the integrators share: light arriving at a shading point straight
// from one light, scattered toward the viewer, through a light sample (shadow ray) or a BSDF
// sample (a ray that may hit the light).
#include <cstdint>

#include "lights/Light.h"
#include "geometry/SceneGeometry.h"
#include "materials/Bsdf.h"

namespace lenslab {

// A ray origin moved off the surface, to the side the ray leaves toward, against self-hits.
Vec3f offsetRayOrigin(const SurfaceHit& hit, Vec3f w);

// How a light sample's estimate is weighted: alone (Whitted), or by the power heuristic against the
// BSDF sampling that the caller also does (path tracing, pbrt-v3's direct lighting).
enum class LightSampleWeight { Alone, Mis };

// f * Li * |cos| / pdf for one sample of `light` chosen with probability `choicePdf`; zero when
// occluded. bsdf: the one at `it`. raysTraced counts the shadow ray.
Vec3f lightSampleEstimate(const SceneGeometry& geometry, const Intersection& it, const Bsdf& bsdf, Vec3f wo,
                          const Light& light, float choicePdf, float u1, float u2, LightSampleWeight weighting,
                          std::uint64_t& raysTraced);

// The MIS-weighted light from `light` that one BSDF sample finds (its emission where the sampled ray
// meets it, or the environment's if it escapes): the other half of pbrt-v3's direct lighting
// estimate. Zero for delta lights and specular samples.
Vec3f bsdfSampleEstimate(const SceneGeometry& geometry, const Intersection& it, const Bsdf& bsdf, Vec3f wo,
                         const Light& light, float uLobe, float u1, float u2, std::uint64_t& raysTraced);

// Radiance that the scene's infinite lights send along an escaped ray's direction d.
Vec3f environmentRadiance(const SceneGeometry& geometry, Vec3f d);

}  // namespace lenslab
