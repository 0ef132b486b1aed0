#include "RayFans.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/PupilAiming.h"
#include "firstorder/FieldOfView.h"
#include "firstorder/ThickLens.h"
#include "trace/ExactTrace.h"
#include "prescription/Pi.h"
#include "LensLayout.h"

namespace lenslab {

namespace {

ZY toZY(const Vec3& p) { return {p.z, p.y}; }

// The point where the ray's line reaches plane z (behind its origin too: the thick lens's planes
// can lie anywhere).
Vec3 onPlaneAt(const Ray& r, double z) { return pointAt(r, (z - r.origin.z) / r.direction.z); }
ZY onPlane(const Ray& r, double z) { return toZY(onPlaneAt(r, z)); }

// A point of a space placed by `space` (LensLayout.h), where the drawing shows it.
ZY drawn(const RigidMotion& space, const Vec3& p) { return LensLayout::place(space, {p.x, p.y, p.z}); }

double objectZ(const LensAnalysis& a) { return a.focus.infinity ? std::numeric_limits<double>::infinity() : a.focus.objectZ; }

struct IncomingRay {
    Ray ray;
    bool offAxis = false;
};

// The field's rays through the stop at `heights` (fractions of its radius, ascending), aimed outward
// from the centre, each starting from its neighbour's solution; nullopt where the aim fails.
std::vector<std::optional<Ray>> aimFan(const LensSystem& lens, const FieldAim& aim, const std::vector<double>& heights) {
    std::vector<std::optional<Ray>> rays(heights.size());
    const long n = static_cast<long>(heights.size());
    const long centre = std::min_element(heights.begin(), heights.end(),
                                         [](double a, double b) { return std::abs(a) < std::abs(b); }) - heights.begin();
    for (long step : {1L, -1L}) {
        AimGuess guess;
        for (long k = centre; k >= 0 && k < n; k += step) rays[k] = aimedRay(lens, aim, 0, heights[k], &guess);
    }
    return rays;
}

// Every field's rays, starting at the object or, when it is farther off than startZ, where they
// cross startZ.
std::vector<IncomingRay> incomingRays(const LensAnalysis& a, const std::vector<double>& fields,
                                      const std::vector<double>& heights, double startZ) {
    std::vector<IncomingRay> rays;
    const double zObject = objectZ(a);
    for (double field : fields) {
        const std::optional<FieldAim> aim = aimField(a.lens, {field, zObject});
        if (!aim) continue;
        for (const std::optional<Ray>& r : aimFan(a.lens, *aim, heights)) {
            if (!r) continue;
            Ray start = *r;
            if (zObject > startZ) start.origin = pointAt(*r, (startZ - r->origin.z) / r->direction.z);
            rays.push_back({start, field != 0});
        }
    }
    return rays;
}

std::vector<double> stopHeights(int rays, double reach) {
    std::vector<double> heights;
    for (int k = 0; k < rays; ++k) heights.push_back(rays == 1 ? 0.0 : reach * (-1.0 + 2.0 * k / (rays - 1)));
    return heights;
}

// Where a blocked ray meets the surface that stopped it, in the surface's own frame: the surface made
// a plain interface (no rim, no bending) to find the hit; its rim's plane when the ray misses the
// surface altogether.
Vec3 blockedAt(const LensSystem& lens, const TraceResult& r) {
    TraceOptions plain;
    plain.ignoreApertures = true;
    SurfaceConstants<double> c = surfaceConstants<double>(lens, r.surface, TraceDirection::SceneToFilm, plain);
    c.eta = 1;
    c.reflects = 0;
    double px = r.ray.origin.x, py = r.ray.origin.y, pz = r.ray.origin.z;
    double dx = r.ray.direction.x, dy = r.ray.direction.y, dz = r.ray.direction.z;
    if (stepThroughSurface(px, py, pz, dx, dy, dz, c) == BlockReason::None) return {px, py, pz};
    const Surface& s = lens.surfaces[r.surface];
    return onPlaneAt(r.ray, s.z - sag(s, s.apertureRadius));
}

// How mirrors stop a ray beyond the sequential trace.
enum class Mirrors {
    Sequential,  // only where the trace itself blocks it: the light's path as if every mirror let it pass
    Solid,       // also where it meets a mirror inside its bore or crosses a mirror's solid part
};

// The exact path, where the drawing shows it: the start, every surface it passes, then the film or the
// point where it stops. With solid mirrors a ray stops too where it meets a mirror inside its bore (the
// light goes into the hole) or crosses a mirror's solid part on its way.
FanRay exactRay(const LensSystem& lens, const LensLayout& layout, const Ray& start, const FanSetup& setup, Mirrors mirrors) {
    const MirrorBores none;
    const MirrorBores& bores = mirrors == Mirrors::Solid ? setup.bores : none;
    std::vector<Vec3> path;
    TraceOptions options;
    options.path = &path;
    const TraceResult r = traceRay(lens, start, TraceDirection::SceneToFilm, options);
    FanRay ray;
    ray.points.push_back(toZY(path[0]));
    for (std::size_t k = 1; k < path.size(); ++k) {
        const int surface = static_cast<int>(k) - 1;
        // The trace records the path in the drawing's coordinates; the bore is the surface's own.
        const auto own = layout.own[surface].inverse().applyToPoint({path[k].x, path[k].y, path[k].z});
        const bool intoBore = lens.surfaces[surface].mirror && std::hypot(own[0], own[1]) < bores.at(surface);
        ray.points.push_back(toZY(path[k]));
        if (intoBore) {
            ray.blocked = true;
            break;
        }
    }
    if (!ray.blocked && !r.ok()) {
        ray.points.push_back(drawn(layout.own[r.surface], blockedAt(lens, r)));
        ray.blocked = true;
    } else if (!ray.blocked && (setup.filmZ - r.ray.origin.z) * r.ray.direction.z > 0) {
        ray.points.push_back(drawn(layout.imageSpace, onPlaneAt(r.ray, setup.filmZ)));
    }
    for (std::size_t k = 1; mirrors == Mirrors::Solid && k < ray.points.size(); ++k) {
        if (const auto crossing = firstSolidMirrorCrossing(lens, layout, bores, ray.points[k - 1], ray.points[k])) {
            ray.points.resize(k);
            ray.points.push_back(*crossing);
            ray.blocked = true;
            break;
        }
    }
    return ray;
}

// The thick lens's path: to the front principal plane P, across to P' at the same height, on to the
// film (P' and the film in image space); a ray outside the entrance pupil stops at its plane.
FanRay thickRay(const ThickLens& thick, const LensLayout& layout, const Ray& start, double filmZ) {
    const TraceResult r = traceThick(thick, start, TraceDirection::SceneToFilm);
    FanRay ray;
    ray.model = RayModel::Thick;
    ray.points.push_back(toZY(start.origin));
    if (!r.ok()) {
        ray.points.push_back(onPlane(start, thick.entrance.z));
        ray.blocked = true;
        return ray;
    }
    ray.points.push_back(onPlane(start, thick.zP));
    ray.points.push_back(drawn(layout.imageSpace, r.ray.origin));
    if ((filmZ - r.ray.origin.z) * r.ray.direction.z > 0) ray.points.push_back(drawn(layout.imageSpace, onPlaneAt(r.ray, filmZ)));
    return ray;
}

std::vector<double> fanFields(const FanSetup& setup) {
    std::vector<double> fields{0.0};
    if (setup.fieldDegrees > 0) fields.push_back(setup.fieldDegrees);
    return fields;
}

std::vector<FanRay> traceIncoming(const LensAnalysis& a, const LensSystem& lens, RayModel model,
                                  const std::vector<IncomingRay>& incoming, const FanSetup& setup,
                                  Mirrors mirrors = Mirrors::Solid) {
    std::vector<FanRay> rays;
    const LensLayout layout = layOutLens(lens);
    for (const IncomingRay& in : incoming) {
        FanRay ray = model == RayModel::Exact ? exactRay(lens, layout, in.ray, setup, mirrors)
                                              : thickRay(a.thick, layout, in.ray, setup.filmZ);
        ray.offAxis = in.offAxis;
        rays.push_back(std::move(ray));
    }
    return rays;
}

std::optional<double> chiefHeight(const LensAnalysis& a, double filmZ, double fieldDegrees) {
    const std::optional<FieldAim> aim = aimField(a.lens, {fieldDegrees, objectZ(a)});
    if (!aim) return std::nullopt;
    const std::optional<Ray> chief = aimedRay(a.lens, *aim, 0, 0);
    if (!chief) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = true;
    const TraceResult out = traceRay(a.lens, *chief, TraceDirection::SceneToFilm, options);
    if (!out.ok()) return std::nullopt;
    const std::optional<Vec3> p = pointOnPlane(out.ray, filmZ);
    if (!p) return std::nullopt;
    return -p->y;
}

}  // namespace

std::vector<FanRay> traceRayFans(const LensAnalysis& analysis, RayModel model, const FanSetup& setup) {
    const auto incoming = incomingRays(analysis, fanFields(setup), stopHeights(setup.rays, kFanOverfill), setup.startZ);
    return traceIncoming(analysis, analysis.lens, model, incoming, setup);
}

std::vector<FanRay> traceColourFans(const LensAnalysis& analysis, const FanSetup& setup) {
    const auto incoming = incomingRays(analysis, fanFields(setup), stopHeights(setup.rays, kFanOverfill), setup.startZ);
    std::vector<FanRay> rays;
    for (double nm : {kWavelengthC, kWavelengthD, kWavelengthF}) {
        for (FanRay& ray : traceIncoming(analysis, atWavelength(analysis.lens, nm), RayModel::Exact, incoming, setup)) {
            ray.wavelength = nm;
            rays.push_back(std::move(ray));
        }
    }
    return rays;
}

double chiefFilmHeight(const LensAnalysis& analysis, double filmZ, double fieldDegrees) {
    if (fieldDegrees == 0) return 0;
    return chiefHeight(analysis, filmZ, fieldDegrees).value_or(0.0);
}

double fieldForFilmHeight(const LensAnalysis& analysis, double filmZ, double height) {
    if (!(height > 0)) return 0;
    // From the paraxial guess outward until the chief ray reaches the height or cannot be traced,
    // then bisection: lo falls short of the height, hi reaches it (or has no chief ray).
    const double guess = std::atan(height / std::abs(analysis.firstOrder.efl)) * 180 / kPi;
    double lo = 0, hi = std::clamp(guess, 1e-3, kWidestSearchedField);
    for (;;) {
        const std::optional<double> h = chiefHeight(analysis, filmZ, hi);
        if (!h || *h >= height) break;
        lo = hi;
        if (hi >= kWidestSearchedField) return hi;
        hi = std::min(kWidestSearchedField, 1.5 * hi);
    }
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        const std::optional<double> h = chiefHeight(analysis, filmZ, mid);
        (h && *h < height ? lo : hi) = mid;
    }
    return chiefHeight(analysis, filmZ, hi) ? hi : lo;
}

double automaticFanField(const LensAnalysis& analysis) {
    if (analysis.field.largestDegrees) return 0.7 * *analysis.field.largestDegrees;
    double radius = 0;
    for (const Surface& s : analysis.lens.surfaces) radius = std::max(radius, s.apertureRadius);
    return std::atan(0.5 * radius / std::abs(analysis.firstOrder.efl)) * 180 / kPi;
}

std::vector<ZY> opticalAxisPath(const LensAnalysis& analysis, const FanSetup& setup) {
    const std::vector<IncomingRay> axis = incomingRays(analysis, {0.0}, {0.0}, setup.startZ);
    if (axis.empty()) return {};
    std::vector<Vec3> path;
    TraceOptions options;
    options.path = &path;
    options.ignoreApertures = true;
    const TraceResult r = traceRay(analysis.lens, axis.front().ray, TraceDirection::SceneToFilm, options);
    std::vector<ZY> points;
    for (const Vec3& p : path) points.push_back(toZY(p));
    if (r.ok() && (setup.filmZ - r.ray.origin.z) * r.ray.direction.z > 0)
        points.push_back(drawn(layOutLens(analysis.lens).imageSpace, onPlaneAt(r.ray, setup.filmZ)));
    return points;
}

std::vector<std::vector<ZY>> passingLightPaths(const LensAnalysis& analysis, const FanSetup& setup) {
    constexpr int kPupilHeights = 17;
    const auto incoming = incomingRays(analysis, fanFields(setup), stopHeights(kPupilHeights, 1.0), setup.startZ);
    std::vector<std::vector<ZY>> paths;
    for (FanRay& ray : traceIncoming(analysis, analysis.lens, RayModel::Exact, incoming, setup, Mirrors::Sequential))
        if (!ray.blocked) paths.push_back(std::move(ray.points));
    return paths;
}

}  // namespace lenslab
