#pragma once
// One ray meeting one surface: a sphere, a conic, an even asphere or another form (FormSag.h).
// Intersection with the cap at the vertex, the clear-aperture and obscuration tests (circles about
// the vertex, or shapes), and vector refraction (or reflection at a mirror). Written once, on plain scalars, so that the scalar trace, the structure-of-arrays batch
// trace and the float variant share the exact same math.
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "prescription/SurfaceAperture.h"
#include "prescription/FormSag.h"

namespace lenslab {

enum class BlockReason : std::uint8_t {
    None = 0,
    MissedSurface,            // no intersection with the surface's cap (or it lies behind the ray)
    OutsideAperture,          // hit beyond the element's clear aperture
    ClippedByStop,            // hit beyond the aperture stop's opening
    TotalInternalReflection,  // no refracted ray exists
    Obscured,                 // hit inside a central obscuration (a reflex lens's secondary mirror)
};

const char* blockReasonName(BlockReason reason);

// A surface's constants in the tracer's arithmetic. The surface, relative to its vertex q = p - vertex,
// is qz + sag(r) = 0 with the even-asphere sag
//     sag(r) = c r^2 / (1 + sqrt(1 - K c^2 r^2)) + sum_i a_i r^(2i),   K = 1 + conic,
// positive toward the film for c > 0. Without polynomial terms it is the quadric
// c (x^2 + y^2 + K qz^2) + 2 qz = 0, which stays exact for flat and nearly flat surfaces.
template <class T>
struct SurfaceConstants {
    T zVertex = 0;
    T curvature = 0;
    T radius = std::numeric_limits<T>::infinity();  // 1 / curvature, taken once per surface
    T conicFactor = 1;                             // K = 1 + conic constant
    T apertureRadius2 = std::numeric_limits<T>::infinity();
    T obscurationRadius2 = 0;
    T eta = 1;           // n_from / n_to
    // These two are an int and a number, not bools: GCC (12) does not vectorise the batch's loop
    // over selects on a byte loaded from the constants ("no vectype for stmt"; RayBatch.cpp).
    int beyondAperture = static_cast<int>(BlockReason::OutsideAperture);  // ClippedByStop at the stop
    T reflects = 0;                                                        // 1 at a mirror
    int asphericTerms = 0;  // how many of `aspheric` are used (0: a quadric)
    T aspheric[8] = {};     // coefficients of r^2, r^4, ..., r^16
};

// The ray's intersection with the quadric's cap at the vertex (where the normal c q + K c qz e_z +
// e_z points toward +z): the root where the line crosses the surface in the sense it travels along z
// (from the +z side to the -z side when dz < 0), as light in a sequential system meets each surface
// from the medium before it. The other root crosses back: where both lie on the cap (a steep ray at a
// strongly curved surface, far outside its rim), taking the nearer one would make the hit depend on
// where along its line the ray starts. Both roots are formed without cancellation (one from Vieta's
// product); at the near one, cc / q, the line's F = a t^2 + 2 b t + cc has slope 2 sign(b) sqrt(disc),
// so it is the forward crossing when b dz >= 0. For a sphere (K = 1) the far root needs no division
// per ray: q * radius. Returns the parameter t; `missed` when that root is off the cap or behind the
// ray. kVirtual (a decentred or folded system, whose surfaces may lie behind the ray: design programs
// propagate it back to them, "virtually"): the nearest root on the cap ahead, else the nearest behind
// (the crossing sense there broke the off-axis mirrors CODV_35571 and zmax_37992: not yet understood).
template <class T, bool kConic, bool kVirtual = false>
inline T intersectQuadric(T px, T py, T qz, T dx, T dy, T dz, const SurfaceConstants<T>& s, bool& missed) {
    const T c = s.curvature, K = kConic ? s.conicFactor : T(1);
    const T b = dz + c * (px * dx + py * dy + K * qz * dz);
    const T cc = c * (px * px + py * py + K * qz * qz) + T(2) * qz;
    const T a = kConic ? c * (T(1) + (K - T(1)) * dz * dz) : c;
    const T disc = b * b - a * cc;
    const T root = std::sqrt(disc > T(0) ? disc : T(0));
    const T q = -(b + (b < T(0) ? -root : root));
    const T tNear = cc / q;  // stays finite as curvature -> 0
    // The other root. A flat surface (or a paraboloid's axial ray) has none: it comes out +-inf or
    // NaN, which the cap test rejects.
    const T tFar = kConic ? q / a : q * s.radius;
    if constexpr (kVirtual) {
        // The nearest root on the cap ahead; without one, the nearest behind.
        const bool nearCap = (std::fabs(tNear) < T(1e30)) & (T(1) + K * c * (qz + tNear * dz) > T(0));
        const bool farCap = (std::fabs(tFar) < T(1e30)) & (T(1) + K * c * (qz + tFar * dz) > T(0));
        const bool nearAhead = nearCap & (tNear >= T(-1e-9)), farAhead = farCap & (tFar >= T(-1e-9));
        const T t = (nearAhead | farAhead) ? (nearAhead & (!farAhead | (tNear <= tFar)) ? tNear : tFar)
                                           : (nearCap & (!farCap | (tNear >= tFar)) ? tNear : tFar);
        missed = !(disc >= T(0)) | !(nearCap | farCap);
        return t;
    }
    const T t = b * dz >= T(0) ? tNear : tFar;
    const bool onCap = (std::fabs(t) < T(1e30)) & (T(1) + K * c * (qz + t * dz) > T(0));
    missed = !(disc >= T(0)) | !onCap | !(t >= T(-1e-9));
    return t;
}

// The even asphere at squared height rho: its sag, g = sag'(r) / r (so the surface's gradient is
// (g x, g y, 1)), and u = 1 - K c^2 rho, which must stay >= 0 (the sag is undefined beyond).
template <class T>
inline void asphereSag(T rho, const SurfaceConstants<T>& s, T& sag, T& g, T& u) {
    const T c = s.curvature;
    u = T(1) - s.conicFactor * c * c * rho;
    const T root = std::sqrt(u > T(0) ? u : T(0));
    T poly = 0, slope = 0;
    for (int i = s.asphericTerms - 1; i >= 0; --i) {
        poly = poly * rho + s.aspheric[i];
        slope = slope * rho + T(2 * (i + 1)) * s.aspheric[i];
    }
    sag = c * rho / (T(1) + root) + poly * rho;
    g = c / (root > T(0) ? root : std::numeric_limits<T>::min()) + slope;
}

// The slope of a surface at (x, y): its gradient is (gx, gy, 1). A surface of revolution keeps the
// one number g = sag'(r) / r (the even asphere's arithmetic, unchanged by the others).
template <class T>
struct RadialSlope {
    T g;
    T along(T x, T y, T dx, T dy) const { return g * (x * dx + y * dy); }
    void normal(T x, T y, T& nx, T& ny) const { nx = g * x, ny = g * y; }
};
template <class T>
struct PlaneSlope {
    T gx, gy;
    T along(T, T, T dx, T dy) const { return gx * dx + gy * dy; }
    void normal(T, T, T& nx, T& ny) const { nx = gx, ny = gy; }
};

// The sag functions Newton walks on: the even asphere of the constants, or a form of FormSag.h.
// Each gives the sag and u (>= 0 where the surface is defined) at (x, y), and the slope there.
template <class T>
struct EvenSag {
    const SurfaceConstants<T>& s;
    RadialSlope<T> operator()(T x, T y, T& sag, T& u) const {
        T g;
        asphereSag(x * x + y * y, s, sag, g, u);
        return {g};
    }
};
template <class T>
struct FormSagOf {
    const FormConstants<T>& form;
    T curvature, conicFactor;
    PlaneSlope<T> operator()(T x, T y, T& sag, T& u) const {
        if (form.kind == SurfaceKind::Toroidal) {
            T gx, gy;
            toroidSag(form, curvature, conicFactor, x, y, sag, gx, gy, u);
            return {gx, gy};
        }
        T g;
        formSag(form, curvature, conicFactor, x * x + y * y, sag, g, u);
        return {g * x, g * y};
    }
};

// One Newton step toward the asphere along the ray from t: F(t) = qz(t) + sag(x(t), y(t)), F' = dz +
// the gradient along (dx, dy). Returns the step taken (0 once F' vanishes; the caller's convergence
// test then fails).
template <class T, class Sag>
inline T asphereNewtonStep(T px, T py, T qz, T dx, T dy, T dz, T t, const Sag& sagOf) {
    const T x = px + t * dx, y = py + t * dy, z = qz + t * dz;
    T sag, u;
    const auto slopeAt = sagOf(x, y, sag, u);
    const T f = z + sag;
    const T slope = dz + slopeAt.along(x, y, dx, dy);
    return slope != T(0) ? -f / slope : T(0);
}

// Newton has converged when its step is below this, relative to the distance travelled: far above
// the rounding of F near the root (so rounding noise cannot stall it), far below any optical length.
template <class T>
inline bool asphereStepConverged(T step, T t) {
    return std::fabs(step) <= T(1024) * std::numeric_limits<T>::epsilon() * (T(1) + std::fabs(t));
}
constexpr int kMaxAsphereIterations = 32;

// Newton's start on an asphere: the base quadric's hit, or where the ray crosses the vertex plane
// when the quadric has none.
template <class T, bool kVirtual = false>
inline T asphereStart(T px, T py, T qz, T dx, T dy, T dz, const SurfaceConstants<T>& s) {
    bool missed = false;
    const T t = intersectQuadric<T, true, kVirtual>(px, py, qz, dx, dy, dz, s, missed);
    return missed ? -qz / dz : t;
}

// After the intersection: the aperture and obscuration tests, then refraction (or reflection) about
// the surface normal (nx, ny, nz), any length, pointing toward +z. Everything is selects rather than
// branches so that the batch loop vectorises; a blocked ray keeps its state. rayEta is the index
// ratio at the ray's own wavelength: s.eta, or one of a spectral batch's (WavelengthEtas.h).
template <class T>
inline BlockReason bendAtHit(T& px, T& py, T& pz, T& dx, T& dy, T& dz, T t, T qz, bool missed, T nx, T ny, T nz,
                             const SurfaceConstants<T>& s, T rayEta) {
    const T hx = px + t * dx, hy = py + t * dy, hqz = qz + t * dz;
    const T r2 = hx * hx + hy * hy;
    const bool outside = r2 > s.apertureRadius2;
    const bool obscured = r2 < s.obscurationRadius2;
    // Normalising keeps refraction unit-length when rounding leaves the hit a little off a tiny,
    // strongly curved surface. Orient the normal against the incoming ray.
    const T inv = T(1) / std::sqrt(nx * nx + ny * ny + nz * nz);
    const T nDotD = (nx * dx + ny * dy + nz * dz) * inv;
    const T sign = nDotD > T(0) ? T(-1) : T(1);
    const T cosi = -sign * nDotD;
    const bool mirror = s.reflects != T(0);
    const T eta = mirror ? T(1) : rayEta;
    const T k = T(1) - eta * eta * (T(1) - cosi * cosi);
    const bool tir = !mirror & !(k >= T(0));
    const bool pass = !missed & !outside & !obscured & !tir;
    // Refraction: eta d + (eta cos i - cos t) n_oriented. Reflection: d + 2 cos i n_oriented.
    const T m = sign * inv * (mirror ? T(2) * cosi : eta * cosi - std::sqrt(k > T(0) ? k : T(0)));
    px = pass ? hx : px;
    py = pass ? hy : py;
    pz = pass ? hqz + s.zVertex : pz;
    const T ex = eta * dx + m * nx, ey = eta * dy + m * ny, ez = eta * dz + m * nz;
    dx = pass ? ex : dx;
    dy = pass ? ey : dy;
    dz = pass ? ez : dz;
    // The first reason that applies, in this order: missed, outside, obscured, total internal
    // reflection; one select after another on ints, which GCC vectorises where a chain of
    // conditionals on the one-byte enum it does not.
    const auto code = [](BlockReason b) { return static_cast<int>(b); };
    int why = tir ? code(BlockReason::TotalInternalReflection) : code(BlockReason::None);
    why = obscured ? code(BlockReason::Obscured) : why;
    why = outside ? s.beyondAperture : why;
    why = missed ? code(BlockReason::MissedSurface) : why;
    return static_cast<BlockReason>(why);
}

// A quadric (sphere when kConic is false): intersection and bend in one step.
template <class T, bool kConic = false, bool kVirtual = false>
inline BlockReason stepThroughQuadric(T& px, T& py, T& pz, T& dx, T& dy, T& dz, const SurfaceConstants<T>& s,
                                      T rayEta) {
    const T qz = pz - s.zVertex;
    bool missed = false;
    const T t = intersectQuadric<T, kConic, kVirtual>(px, py, qz, dx, dy, dz, s, missed);
    const T c = s.curvature, K = kConic ? s.conicFactor : T(1);
    const T hx = px + t * dx, hy = py + t * dy, hqz = qz + t * dz;
    return bendAtHit(px, py, pz, dx, dy, dz, t, qz, missed, c * hx, c * hy, T(1) + K * c * hqz, s, rayEta);
}

// The asphere's bend once Newton has its t (shared by the scalar and the batch trace).
template <class T, class Sag, bool kVirtual = false>
inline BlockReason finishAsphere(T& px, T& py, T& pz, T& dx, T& dy, T& dz, T t, T qz, bool converged,
                                 const SurfaceConstants<T>& s, T rayEta, const Sag& sagOf) {
    const T hx = px + t * dx, hy = py + t * dy;
    T sag, u, nx, ny;
    sagOf(hx, hy, sag, u).normal(hx, hy, nx, ny);
    const bool ahead = kVirtual ? std::fabs(t) < T(1e30) : (t >= T(-1e-9)) & (t < T(1e30));
    const bool missed = !converged | !ahead | !(u >= T(0));
    return bendAtHit(px, py, pz, dx, dy, dz, t, qz, missed, nx, ny, T(1), s, rayEta);
}

// An asphere: Newton from the base quadric's hit, converged per ray; a ray that does not converge,
// or ends where the sag is undefined, missed the surface.
template <class T, class Sag, bool kVirtual = false>
inline BlockReason stepThroughAsphere(T& px, T& py, T& pz, T& dx, T& dy, T& dz, const SurfaceConstants<T>& s,
                                      T rayEta, const Sag& sagOf) {
    const T qz = pz - s.zVertex;
    T t = asphereStart<T, kVirtual>(px, py, qz, dx, dy, dz, s);
    bool converged = false;
    for (int i = 0; i < kMaxAsphereIterations && !converged && std::isfinite(t); ++i) {
        const T step = asphereNewtonStep(px, py, qz, dx, dy, dz, t, sagOf);
        t += step;
        converged = asphereStepConverged(step, t);
    }
    return finishAsphere<T, Sag, kVirtual>(px, py, pz, dx, dy, dz, t, qz, converged, s, rayEta, sagOf);
}

// Any centred, circular, even surface, for one ray.
template <class T, bool kVirtual = false>
inline BlockReason stepThroughSurface(T& px, T& py, T& pz, T& dx, T& dy, T& dz, const SurfaceConstants<T>& s,
                                      T rayEta) {
    if (s.asphericTerms > 0)
        return stepThroughAsphere<T, EvenSag<T>, kVirtual>(px, py, pz, dx, dy, dz, s, rayEta, EvenSag<T>{s});
    if (s.conicFactor != T(1)) return stepThroughQuadric<T, true, kVirtual>(px, py, pz, dx, dy, dz, s, rayEta);
    return stepThroughQuadric<T, false, kVirtual>(px, py, pz, dx, dy, dz, s, rayEta);
}
template <class T>
inline BlockReason stepThroughSurface(T& px, T& py, T& pz, T& dx, T& dy, T& dz, const SurfaceConstants<T>& s) {
    return stepThroughSurface<T>(px, py, pz, dx, dy, dz, s, s.eta);
}

// What only the general step reads: the surface's form and its shaped apertures (the constants'
// circles are then opened to infinity and none), and whether the ray may meet it behind itself (a
// decentred or tilted lens, intersectQuadric's kVirtual).
template <class T>
struct GeneralSurface {
    FormConstants<T> form;
    std::optional<SurfaceAperture> clear, obscuration;
    bool virtualPropagation = false;
};

template <class T, bool kVirtual>
inline BlockReason stepThroughForm(T& px, T& py, T& pz, T& dx, T& dy, T& dz, const SurfaceConstants<T>& s,
                                   const GeneralSurface<T>& g, T rayEta) {
    if (g.form.kind == SurfaceKind::EvenAsphere) return stepThroughSurface<T, kVirtual>(px, py, pz, dx, dy, dz, s, rayEta);
    const FormSagOf<T> sagOf{g.form, s.curvature, s.conicFactor};
    return stepThroughAsphere<T, FormSagOf<T>, kVirtual>(px, py, pz, dx, dy, dz, s, rayEta, sagOf);
}

// A surface with a form beyond the even asphere, a shaped aperture, or in a decentred lens. A ray
// the shapes block keeps the state it arrived with, as bendAtHit keeps it.
template <class T>
inline BlockReason stepThroughGeneral(T& px, T& py, T& pz, T& dx, T& dy, T& dz, const SurfaceConstants<T>& s,
                                      const GeneralSurface<T>& g, T rayEta) {
    const T x0 = px, y0 = py, z0 = pz, u0 = dx, v0 = dy, w0 = dz;
    const BlockReason why = g.virtualPropagation ? stepThroughForm<T, true>(px, py, pz, dx, dy, dz, s, g, rayEta)
                                                 : stepThroughForm<T, false>(px, py, pz, dx, dy, dz, s, g, rayEta);
    if (why != BlockReason::None) return why;
    const double hx = double(px), hy = double(py);
    const BlockReason shaped = g.clear && !g.clear->contains(hx, hy)
                                   ? static_cast<BlockReason>(s.beyondAperture)
                               : g.obscuration && g.obscuration->contains(hx, hy) ? BlockReason::Obscured
                                                                                  : BlockReason::None;
    if (shaped != BlockReason::None) {
        px = x0, py = y0, pz = z0, dx = u0, dy = v0, dz = w0;
    }
    return shaped;
}

}  // namespace lenslab
