#include "trace/AxisRay.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

// The object-space ray of parameters (u, v): across the axis at the start plane for an object at
// infinity, the direction's x and y from the axial object point otherwise.
Ray fieldZeroRay(const LensSystem& lens, double u, double v, double zIn) {
    if (!std::isfinite(lens.objectDistance)) return {{u, v, zIn}, {0, 0, -1}};
    const Vec3 object{0, 0, lens.frontZ() + lens.objectDistance};
    return {object, normalize({u, v, -1})};
}

// A rotation taking the unit vector d to (0, 0, -1) about their common perpendicular.
std::array<double, 9> rotationOnto(const Vec3& d) {
    const Vec3 t{0, 0, -1};
    const Vec3 axis{d.y * t.z - d.z * t.y, d.z * t.x - d.x * t.z, d.x * t.y - d.y * t.x};
    const double s = length(axis), c = dot(d, t);
    if (s < 1e-300) return c > 0 ? std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1}
                                 : std::array<double, 9>{1, 0, 0, 0, -1, 0, 0, 0, -1};
    const Vec3 k = (1 / s) * axis;
    const double v = 1 - c;
    return {c + k.x * k.x * v,       k.x * k.y * v - k.z * s, k.x * k.z * v + k.y * s,
            k.y * k.x * v + k.z * s, c + k.y * k.y * v,       k.y * k.z * v - k.x * s,
            k.z * k.x * v - k.y * s, k.z * k.y * v + k.x * s, c + k.z * k.z * v};
}

}  // namespace

std::optional<Vec3> stopCrossing(const LensSystem& lens, const Ray& ray) {
    TraceOptions options;
    options.end = lens.stopIndex + 1;
    options.ignoreApertures = true;
    const TraceResult r = traceRay(lens, ray, TraceDirection::SceneToFilm, options);
    if (!r.ok()) return std::nullopt;
    // Out of the stop toward the film the coordinates moved by its `after`: undone (a centred stop's
    // is the identity, and the aiming's Newton calls this for every step).
    const RigidMotion& out = lens.stop().after;
    if (out.isIdentity()) return r.ray.origin;
    const auto p = out.inverse().applyToPoint({r.ray.origin.x, r.ray.origin.y, r.ray.origin.z});
    return Vec3{p[0], p[1], p[2]};
}

std::optional<Ray> axisRay(const LensSystem& lens) {
    double reach = 0;
    for (const Surface& s : lens.surfaces) reach = std::max(reach, s.apertureRadius);
    const double zIn = lens.frontZ() + lens.surfaces.front().apertureRadius + 1.0;
    // Newton on (u, v) -> the stop hit's (x, y), with a finite-difference Jacobian: the map is
    // smooth and near linear across the stop.
    const bool infinite = !std::isfinite(lens.objectDistance);
    const double step = infinite ? 1e-6 * std::max(reach, 1.0) : 1e-7;
    double u = 0, v = 0;
    for (int it = 0; it < 30; ++it) {
        const auto h = stopCrossing(lens, fieldZeroRay(lens, u, v, zIn));
        const auto hu = stopCrossing(lens, fieldZeroRay(lens, u + step, v, zIn));
        const auto hv = stopCrossing(lens, fieldZeroRay(lens, u, v + step, zIn));
        if (!h || !hu || !hv) return std::nullopt;
        if (std::hypot(h->x, h->y) <= 1e-13 * std::max(reach, 1.0)) return fieldZeroRay(lens, u, v, zIn);
        const double a = (hu->x - h->x) / step, b = (hv->x - h->x) / step;
        const double c = (hu->y - h->y) / step, d = (hv->y - h->y) / step;
        const double det = a * d - b * c;
        if (!(std::fabs(det) > 0)) return std::nullopt;
        u -= (d * h->x - b * h->y) / det;
        v -= (a * h->y - c * h->x) / det;
    }
    return std::nullopt;
}

std::optional<AxisAtStop> axisRayAtStop(const LensSystem& lens) {
    const std::optional<Ray> in = axisRay(lens);
    if (!in) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = true;
    options.end = lens.stopIndex;
    const TraceResult before = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    options.end = lens.stopIndex + 1;
    const TraceResult after = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    if (!before.ok() || !after.ok()) return std::nullopt;
    const Surface& stop = lens.stop();
    return AxisAtStop{movedRay(motionInto(stop, TraceDirection::SceneToFilm), before.ray).direction,
                      movedRay(motionOutOf(stop, TraceDirection::SceneToFilm).inverse(), after.ray).direction};
}

LensSystem alongAxisRay(const LensSystem& lens) {
    if (!lens.hasMovedSurfaces() && std::none_of(lens.surfaces.begin(), lens.surfaces.end(),
                                                 [](const Surface& s) { return s.clearShape.has_value(); }))
        return lens;
    const std::optional<Ray> in = axisRay(lens);
    if (!in) return lens;
    TraceOptions options;
    options.ignoreApertures = true;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    if (!out.ok()) return lens;
    LensSystem aligned = lens;
    // Object space: the axis ray's crossing of the start plane becomes x = y = 0.
    if (!std::isfinite(lens.objectDistance) && (in->origin.x != 0 || in->origin.y != 0)) {
        RigidMotion shift;
        shift.shift = {in->origin.x, in->origin.y, 0};
        aligned.surfaces.front().before = shift.then(aligned.surfaces.front().before);
    }
    // Image space: turned about the last vertex onto -z, then shifted across.
    const Vec3 d = out.ray.direction, p = out.ray.origin;
    const double zLast = lens.rearZ();
    if (std::fabs(d.x) + std::fabs(d.y) > 1e-15 || d.z > 0 || std::fabs(p.x) + std::fabs(p.y) > 1e-12 * std::max(1.0, std::fabs(zLast))) {
        RigidMotion turn;
        turn.rotation = rotationOnto(d);
        const auto pivot = turn.applyToDirection({0, 0, zLast});
        turn.shift = {-pivot[0], -pivot[1], zLast - pivot[2]};
        const auto q = turn.applyToPoint({p.x, p.y, p.z});
        turn.shift[0] -= q[0];
        turn.shift[1] -= q[1];
        aligned.surfaces.back().after = aligned.surfaces.back().after.then(turn);
    }
    return aligned;
}

}  // namespace lenslab
