#include "analysis/PupilAiming.h"

#include <algorithm>
#include <cmath>

#include "firstorder/ChiefRay.h"
#include "trace/AxisRay.h"
#include "trace/ExactTrace.h"
#include "firstorder/Pupils.h"
#include "prescription/Pi.h"

namespace lenslab {

namespace {

Ray rayThrough(const FieldAim& aim, double u, double v) {
    const Vec3 p{u, v, aim.aimZ};
    if (std::isinf(aim.field.objectZ)) return {p, aim.direction};
    return {aim.objectPoint, normalize(p - aim.objectPoint)};
}

struct StopPoint {
    double x = 0, y = 0;
};

// Where the ray meets the stop surface, in the stop's own frame (a decentred stop's centre is off
// the axis of the coordinates arriving at it), every aperture ignored; nullopt when it cannot get there.
std::optional<StopPoint> stopPoint(const LensSystem& lens, const Ray& ray) {
    const std::optional<Vec3> p = stopCrossing(lens, ray);
    if (!p) return std::nullopt;
    return StopPoint{p->x, p->y};
}

// Fills aim.inverseJacobian at the aim point (u, v) by differences; returns the stop point there.
std::optional<StopPoint> linearise(const LensSystem& lens, FieldAim& aim, double u, double v, double step) {
    const auto s = stopPoint(lens, rayThrough(aim, u, v));
    const auto su = stopPoint(lens, rayThrough(aim, u + step, v));
    const auto sv = stopPoint(lens, rayThrough(aim, u, v + step));
    if (!s || !su || !sv) return std::nullopt;
    const double a = (su->x - s->x) / step, b = (sv->x - s->x) / step;
    const double c = (su->y - s->y) / step, d = (sv->y - s->y) / step;
    const double det = a * d - b * c;
    if (!(std::fabs(det) > 0)) return std::nullopt;
    aim.inverseJacobian[0][0] = d / det, aim.inverseJacobian[0][1] = -b / det;
    aim.inverseJacobian[1][0] = -c / det, aim.inverseJacobian[1][1] = a / det;
    return s;
}

// Newton for a finite object's chief ray (the distortion code searches only distant objects'): from
// the aim plane's axis point to the aim point whose ray crosses the stop's centre.
bool solveChief(const LensSystem& lens, FieldAim& aim, double step) {
    double u = 0, v = 0;
    for (int it = 0; it < 30; ++it) {
        const auto s = linearise(lens, aim, u, v, step);
        if (!s) return false;
        // 1e-9 of the stop's radius: at 1e-12 the rounding of a finite object's ray at the stop kept
        // Newton from ever passing at some angles, and those fields went untraced.
        if (std::hypot(s->x, s->y) < 1e-9 * aim.stopRadius) {
            aim.chiefAimX = u;
            aim.chiefAimY = v;
            return true;
        }
        u -= aim.inverseJacobian[0][0] * s->x + aim.inverseJacobian[0][1] * s->y;
        v -= aim.inverseJacobian[1][0] * s->x + aim.inverseJacobian[1][1] * s->y;
    }
    return false;
}

}  // namespace

std::optional<FieldAim> aimField(const LensSystem& lens, const ObjectField& field) {
    FieldAim aim;
    aim.field = field;
    aim.stopRadius = lens.stop().apertureRadius;
    const double theta = field.fieldDegrees * kPi / 180;
    const double step = 1e-4 * aim.stopRadius;
    if (std::isinf(field.objectZ)) {
        // The distortion code's chief-ray search copes with the strongest pupil aberration (fisheyes).
        const std::optional<Ray> chief = chiefRay(lens, field.fieldDegrees);
        if (!chief) return std::nullopt;
        aim.aimZ = chief->origin.z;
        aim.direction = chief->direction;
        aim.chiefAimX = chief->origin.x;
        aim.chiefAimY = chief->origin.y;
        if (!linearise(lens, aim, aim.chiefAimX, aim.chiefAimY, step)) return std::nullopt;
        return aim;
    }
    const Pupils pupils = computePupils(lens);
    aim.aimZ = pupils.entrance.z;
    aim.objectPoint = {0, (field.objectZ - pupils.entrance.z) * std::tan(theta), field.objectZ};
    if (!solveChief(lens, aim, step)) return std::nullopt;
    return aim;
}

std::optional<Ray> aimedRay(const LensSystem& lens, const FieldAim& aim, double px, double py, AimGuess* guess) {
    // Aimed a hair inside the asked point, so that a ray asked for the stop's rim is not clipped by
    // the rounding of the aim.
    constexpr double kInside = 1 - 1e-9;
    const double tx = px * aim.stopRadius * kInside, ty = py * aim.stopRadius * kInside;
    double J[2][2];
    double u = aim.chiefAimX, v = aim.chiefAimY;  // the start (the chief ray's: the stop's centre)
    StopPoint s;                                   // and where it crosses the stop
    if (guess && guess->valid) {
        std::copy(&guess->inverseJacobian[0][0], &guess->inverseJacobian[0][0] + 4, &J[0][0]);
        u = guess->aimX, v = guess->aimY, s = {guess->stopX, guess->stopY};
    } else {
        std::copy(&aim.inverseJacobian[0][0], &aim.inverseJacobian[0][0] + 4, &J[0][0]);
    }
    // Broyden's method from the start's Jacobian: one trace per step, the inverse Jacobian updated
    // by each step's secant.
    for (int it = 0; it < 40; ++it) {
        const double rx = tx - s.x, ry = ty - s.y;
        if (std::hypot(rx, ry) <= 1e-10 * aim.stopRadius) {
            if (guess) *guess = {true, u, v, s.x, s.y, {{J[0][0], J[0][1]}, {J[1][0], J[1][1]}}};
            return rayThrough(aim, u, v);
        }
        double du = J[0][0] * rx + J[0][1] * ry, dv = J[1][0] * rx + J[1][1] * ry;
        std::optional<StopPoint> next = stopPoint(lens, rayThrough(aim, u + du, v + dv));
        // A step past where the rays still reach the stop (beyond the fold where they graze a steep
        // surface, just outside the rim of a concave stop at a steep field) is halved back toward
        // the last ray that did: the asked point lies on this side of the fold.
        for (int halving = 0; halving < 30 && !next; ++halving) {
            du *= 0.5, dv *= 0.5;
            next = stopPoint(lens, rayThrough(aim, u + du, v + dv));
        }
        if (!next) return std::nullopt;
        u += du, v += dv;
        const double fx = next->x - s.x, fy = next->y - s.y;                     // change of the stop point
        const double jfx = J[0][0] * fx + J[0][1] * fy, jfy = J[1][0] * fx + J[1][1] * fy;
        const double denom = du * jfx + dv * jfy;
        if (std::fabs(denom) > 0) {
            const double ex = (du - jfx) / denom, ey = (dv - jfy) / denom;
            const double rowX = du * J[0][0] + dv * J[1][0], rowY = du * J[0][1] + dv * J[1][1];  // step^T J
            J[0][0] += ex * rowX, J[0][1] += ex * rowY;
            J[1][0] += ey * rowX, J[1][1] += ey * rowY;
        }
        s = *next;
    }
    return std::nullopt;
}

std::optional<Vec3> pointOnPlane(const Ray& ray, double z) {
    if (ray.direction.z == 0) return std::nullopt;
    return pointAt(ray, (z - ray.origin.z) / ray.direction.z);
}

std::optional<ImageSpaceAperture> imageSpaceAperture(const LensSystem& lens, const FieldAim& aim) {
    TraceOptions options;
    options.ignoreApertures = true;
    auto exitDirection = [&](double px, double py) -> std::optional<Vec3> {
        const std::optional<Ray> in = aimedRay(lens, aim, px, py);
        if (!in) return std::nullopt;
        const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
        if (!out.ok()) return std::nullopt;
        return out.ray.direction;
    };
    // The rim first; a smaller ring when the rim rays cannot be aimed (a fisheye's far field).
    for (double rim : {1.0, 0.5, 0.25}) {
        const auto xPlus = exitDirection(rim, 0), xMinus = exitDirection(-rim, 0);
        const auto yPlus = exitDirection(0, rim), yMinus = exitDirection(0, -rim);
        if (xPlus && xMinus && yPlus && yMinus)
            return ImageSpaceAperture{(xPlus->x - xMinus->x) / (2 * rim), (yPlus->y - yMinus->y) / (2 * rim)};
    }
    return std::nullopt;
}

}  // namespace lenslab
