#include "RayFans.h"

#include <algorithm>
#include <cmath>

#include "trace/ExactTrace.h"
#include "firstorder/ThickLens.h"

namespace lenslab {

namespace {

ZY toZY(const Vec3& p) { return {p.z, p.y}; }

// The point where the ray reaches plane z (the ray's own origin when the plane lies behind it).
ZY atPlane(const Ray& r, double z) {
    const double t = r.direction.z != 0 ? std::max(0.0, (z - r.origin.z) / r.direction.z) : 0.0;
    return toZY(pointAt(r, t));
}

Ray filmRay(ZY film, ZY target) {
    return {{0, film.y, film.z}, normalize(Vec3{0, target.y - film.y, target.z - film.z})};
}

FanRay exactRay(const LensSystem& lens, const Ray& start, double endZ) {
    std::vector<Vec3> path;
    TraceOptions options;
    options.path = &path;
    const TraceResult r = traceRay(lens, start, TraceDirection::FilmToScene, options);
    FanRay ray;
    for (const Vec3& p : path) ray.points.push_back(toZY(p));
    if (!r.ok()) {
        // The ray stops where it meets the blocking surface's rim plane (the stop, an element's edge).
        const Surface& s = lens.surfaces[r.surface];
        ray.points.push_back(atPlane(r.ray, s.z - sag(s, s.apertureRadius)));
        ray.blocked = true;
    } else if (r.ray.direction.z > 0 && endZ > r.ray.origin.z) {
        ray.points.push_back(atPlane(r.ray, endZ));
    }
    return ray;
}

FanRay thickRay(const ThickLens& thick, const Ray& start, double endZ) {
    const TraceResult r = traceThick(thick, start, TraceDirection::FilmToScene);
    FanRay ray;
    ray.model = RayModel::Thick;
    ray.points.push_back(toZY(start.origin));
    if (!r.ok()) {
        // The exit pupil stands in for the stop.
        ray.points.push_back(atPlane(start, thick.exit.z));
        ray.blocked = true;
        return ray;
    }
    // In at P' and out at P at the same height.
    ray.points.push_back(atPlane(start, thick.zPPrime));
    ray.points.push_back(toZY(r.ray.origin));
    if (endZ > r.ray.origin.z) ray.points.push_back(atPlane(r.ray, endZ));
    return ray;
}

}  // namespace

std::vector<FanRay> traceRayFans(const LensAnalysis& analysis, RayModel model, const FanSetup& setup) {
    const Pupil& exit = analysis.pupils.exit;
    std::vector<FanRay> rays;
    std::vector<double> heights{0.0};
    if (setup.fieldHeight > 0) heights.push_back(-setup.fieldHeight);
    for (double h : heights) {
        for (int k = 0; k < setup.rays; ++k) {
            const double s = setup.rays == 1 ? 0.0 : -1.0 + 2.0 * k / (setup.rays - 1);
            const Ray start = filmRay({setup.filmZ, h}, {exit.z, s * kFanOverfill * exit.diameter / 2});
            FanRay ray = model == RayModel::Exact ? exactRay(analysis.lens, start, setup.endZ)
                                                  : thickRay(analysis.thick, start, setup.endZ);
            ray.offAxis = h != 0.0;
            rays.push_back(std::move(ray));
        }
    }
    return rays;
}

std::vector<FanRay> traceColourFans(const LensAnalysis& analysis, const FanSetup& setup) {
    std::vector<FanRay> rays;
    LensAnalysis atLine = analysis;
    for (double nm : {kWavelengthC, kWavelengthD, kWavelengthF}) {
        atLine.lens = atWavelength(analysis.lens, nm);
        for (FanRay& ray : traceRayFans(atLine, RayModel::Exact, setup)) {
            ray.wavelength = nm;
            rays.push_back(std::move(ray));
        }
    }
    return rays;
}

double automaticFieldHeight(const LensAnalysis& analysis, double filmZ) {
    const double exitZ = analysis.pupils.exit.z;
    // A reflex lens's obscuration takes every chief ray: the field is set by the rims.
    TraceOptions options;
    options.ignoreObscurations = true;
    auto chiefPasses = [&](double h) {
        const Ray r = filmRay({filmZ, -h}, {exitZ, 0});
        return traceRay(analysis.lens, r, TraceDirection::FilmToScene, options).ok();
    };
    // March out to the first blocked height, then bisect the edge.
    const double step = 0.02 * std::abs(analysis.firstOrder.efl);
    const double limit = 3.0 * std::abs(analysis.firstOrder.efl);
    double good = 0, bad = limit;
    for (double h = step; h <= limit; h += step) {
        if (!chiefPasses(h)) {
            bad = h;
            break;
        }
        good = h;
    }
    for (int i = 0; i < 30 && bad - good > 1e-4 * step; ++i) {
        const double mid = 0.5 * (good + bad);
        (chiefPasses(mid) ? good : bad) = mid;
    }
    return 0.7 * good;
}

}  // namespace lenslab
