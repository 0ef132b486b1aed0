#pragma once
// One ray meeting one spherical (or flat) surface: intersection with the cap at the vertex, the
// clear-aperture test, and vector refraction. Written once, on plain scalars, so that the scalar
// trace, the structure-of-arrays batch trace and the float variant share the exact same math.
#include <cmath>
#include <cstdint>
#include <limits>

namespace lenslab {

enum class BlockReason : std::uint8_t {
    None = 0,
    MissedSurface,            // no intersection with the surface's cap (or it lies behind the ray)
    OutsideAperture,          // hit beyond the element's clear aperture
    ClippedByStop,            // hit beyond the aperture stop's opening
    TotalInternalReflection,  // no refracted ray exists
};

const char* blockReasonName(BlockReason reason);

// Advances the ray (p, d) to the surface with vertex at zVertex and the given curvature, and refracts
// it from index ratio eta = n_from / n_to. The surface equation relative to the vertex,
// c |q|^2 + 2 q_z = 0 with q = p - vertex (centre at z = vertex - radius), stays exact for flat and
// nearly flat surfaces. Both roots are formed without cancellation (one from Vieta's product); the
// hit is the nearest one ahead of the ray on the cap at the vertex, the hemisphere where the unit
// normal c q + e_z points toward +z. On a block the ray is left untouched and the reason returned.
// radius is 1 / curvature (infinite for a flat surface), taken by the caller once per surface: the
// far root's division per ray would be one of the step's six divisions and square roots, which
// bound the vectorised batch.
template <class T>
inline BlockReason stepThroughSurface(T& px, T& py, T& pz, T& dx, T& dy, T& dz, T zVertex,
                                      T curvature, T radius, T apertureRadius2, T eta, bool isStop) {
    const T qz = pz - zVertex;
    const T b = dz + curvature * (px * dx + py * dy + qz * dz);
    const T c = curvature * (px * px + py * py + qz * qz) + T(2) * qz;
    const T disc = b * b - curvature * c;
    const T root = std::sqrt(disc > T(0) ? disc : T(0));
    const T q = -(b + (b < T(0) ? -root : root));
    const T tNear = c / q;  // stays finite as curvature -> 0
    // The other root. A flat surface has none: q * inf is +-inf (or NaN), which farOk rejects.
    const T tFar = q * radius;
    const T tMin = T(-1e-9);
    const bool nearOk = (tNear >= tMin) & (T(1) + curvature * (qz + tNear * dz) > T(0));
    const bool farOk = (tFar >= tMin) & (tFar < T(1e30)) & (T(1) + curvature * (qz + tFar * dz) > T(0));
    const T t = nearOk & (!farOk | (tNear <= tFar)) ? tNear : tFar;
    const T hx = px + t * dx, hy = py + t * dy, hqz = qz + t * dz;
    const T nzCap = T(1) + curvature * hqz;
    const bool missed = !(disc >= T(0)) | !(nearOk | farOk) | !(t < T(1e30));
    const bool outside = hx * hx + hy * hy > apertureRadius2;

    // The normal c q + e_z is unit length on the sphere; normalising it anyway keeps refraction
    // unit-length when rounding leaves the hit a little off a tiny, strongly curved surface.
    // Orient it against the incoming ray. Everything below is selects rather than branches so that
    // the batch loop vectorises; a blocked ray keeps its state.
    const T nx = curvature * hx, ny = curvature * hy;
    const T inv = T(1) / std::sqrt(nx * nx + ny * ny + nzCap * nzCap);
    const T nDotD = (nx * dx + ny * dy + nzCap * dz) * inv;
    const T sign = nDotD > T(0) ? T(-1) : T(1);
    const T cosi = -sign * nDotD;
    const T k = T(1) - eta * eta * (T(1) - cosi * cosi);
    const bool tir = !(k >= T(0));
    const bool pass = !missed & !outside & !tir;
    const T m = sign * inv * (eta * cosi - std::sqrt(k > T(0) ? k : T(0)));
    px = pass ? hx : px;
    py = pass ? hy : py;
    pz = pass ? hqz + zVertex : pz;
    const T ex = eta * dx + m * nx, ey = eta * dy + m * ny, ez = eta * dz + m * nzCap;
    dx = pass ? ex : dx;
    dy = pass ? ey : dy;
    dz = pass ? ez : dz;
    return missed    ? BlockReason::MissedSurface
           : outside ? (isStop ? BlockReason::ClippedByStop : BlockReason::OutsideAperture)
           : tir     ? BlockReason::TotalInternalReflection
                     : BlockReason::None;
}

}  // namespace lenslab
