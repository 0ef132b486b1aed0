#include "cameras/ThickLensFilmError.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/RelativeIllumination.h"
#include "prescription/OpticsError.h"
#include "trace/RayBatch.h"

namespace lenslab {

namespace {


// Where the ray crosses the plane z = planeZ; false when it runs away from the plane.
bool crossPlane(const Ray& ray, double planeZ, double& x, double& y) {
    if (!(ray.direction.z > 0)) return false;
    const double t = (planeZ - ray.origin.z) / ray.direction.z;
    x = ray.origin.x + t * ray.direction.x;
    y = ray.origin.y + t * ray.direction.y;
    return std::isfinite(x) && std::isfinite(y);
}

// The thick lens's ray from film point (r, 0) through the exit pupil's centre.
TraceResult thickChiefRay(const LensAnalysis& a, double r) {
    const Vec3 from{r, 0, a.focus.imageZThick};
    const Vec3 to{0, 0, a.thick.exit.z};
    return traceThick(a.thick, {from, normalize(to - from)}, TraceDirection::FilmToScene);
}

// Film irradiance (up to the radiance) of the thick lens at film point (r, 0): the exit pupil
// disc seen from the film, cos^4 / dz^2 per unit pupil area, summed over a grid.
double thickIrradiance(const LensAnalysis& a, double r, int cells) {
    const Pupil& xp = a.thick.exit;
    const double radius = 0.5 * xp.diameter, cell = 2.0 * radius / cells;
    const double dz = xp.z - a.focus.imageZThick;
    double sum = 0;
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const double x = -radius + (i + 0.5) * cell, y = -radius + (j + 0.5) * cell;
            if (x * x + y * y > radius * radius) continue;
            sum += cos4(dz / std::sqrt((x - r) * (x - r) + y * y + dz * dz));
        }
    return sum * cell * cell / (dz * dz);
}

// Exact rays from film point (r, 0, filmZ) aimed at the y >= 0 half of a grid on the aiming plane
// (the rear vertex).
struct ExactFan {
    RayBatch batch;
    std::vector<double> cosines;  // of each ray's angle to the axis, film side
    double cellArea = 0;
    double minX = 0, maxX = 0, maxY = 0;  // the passing rays' aim points
    bool any = false;
    bool touchesRim = false;  // a passing ray within a cell and a half of the rim
};

ExactFan traceExactFan(const LensSystem& lens, double filmZ, double r, double x0, double x1, double y1, int cellsX,
                       int cellsY) {
    ExactFan fan;
    const double cellX = (x1 - x0) / cellsX, cellY = y1 / cellsY;
    fan.cellArea = cellX * cellY;
    fan.batch.resize(std::size_t(cellsX) * cellsY);
    fan.cosines.resize(fan.batch.size());
    const Vec3 from{r, 0, filmZ};
    for (int j = 0, k = 0; j < cellsY; ++j)
        for (int i = 0; i < cellsX; ++i, ++k) {
            const Vec3 d = normalize(Vec3{x0 + (i + 0.5) * cellX, (j + 0.5) * cellY, lens.rearZ()} - from);
            fan.batch.set(k, {from, d});
            fan.cosines[k] = d.z;
        }
    traceBatch(lens, fan.batch, TraceDirection::FilmToScene);
    for (int j = 0, k = 0; j < cellsY; ++j)
        for (int i = 0; i < cellsX; ++i, ++k) {
            if (fan.batch.blocked[k] != BlockReason::None) continue;
            const double x = x0 + (i + 0.5) * cellX, y = (j + 0.5) * cellY;
            fan.minX = fan.any ? std::min(fan.minX, x) : x;
            fan.maxX = fan.any ? std::max(fan.maxX, x) : x;
            fan.maxY = std::max(fan.maxY, y);
            fan.any = true;
            if (i < 2 || i >= cellsX - 2 || j >= cellsY - 2) fan.touchesRim = true;
        }
    return fan;
}

// A coarse grid (widened until no passing ray touches its rim, refined when a small stop slips
// through it) finds where the passing rays aim; a fine grid of `cells` over that box then samples
// them. The search keeps its own 32 cells: a finer one would only multiply the rays spent on film
// radii that nothing passes (a fisheye's outer third).
ExactFan sampleExactRays(const LensSystem& lens, double filmZ, double r, int cells) {
    constexpr int kSearchCells = 32;
    double extent = 1.5 * lens.surfaces.back().apertureRadius;
    ExactFan coarse = traceExactFan(lens, filmZ, r, -extent, extent, extent, kSearchCells, kSearchCells / 2);
    for (int grow = 0; grow < 4 && coarse.touchesRim; ++grow) {
        extent *= 2;
        coarse = traceExactFan(lens, filmZ, r, -extent, extent, extent, kSearchCells, kSearchCells / 2);
    }
    if (!coarse.any)
        coarse = traceExactFan(lens, filmZ, r, -extent, extent, extent, 8 * kSearchCells, 4 * kSearchCells);
    if (!coarse.any) return coarse;
    const double pad = 2.0 * extent / kSearchCells;
    return traceExactFan(lens, filmZ, r, coarse.minX - pad, coarse.maxX + pad, coarse.maxY + pad, cells, cells / 2);
}

}  // namespace

ComparisonPlane comparisonPlane(const LensAnalysis& a) {
    ComparisonPlane plane;
    plane.z = a.focus.infinity ? 1e6 * a.firstOrder.efl : a.focus.objectZ;
    // The thick lens images the film plane onto the plane of focus at one magnification.
    const double unitRadius = 1.0;
    double x = 0, y;
    const TraceResult unit = thickChiefRay(a, unitRadius);
    if (!unit.ok() || !crossPlane(unit.ray, plane.z, x, y) || x == 0)
        throw OpticsError("thick-lens error: the thick lens does not image the film onto the plane of focus");
    plane.magnification = x / unitRadius;
    return plane;
}

std::vector<ThickLensFilmError> measureThickLensFilmError(const LensAnalysis& a, double minFilmRadius,
                                                          double maxFilmRadius, const ThickLensFilmErrorOptions& o) {
    if (!(minFilmRadius >= 0 && minFilmRadius <= maxFilmRadius) || o.filmRadii < 2 || o.pupilGrid < 4)
        throw OpticsError("thick-lens error: need 0 <= minimum film radius <= maximum, 2+ radii, a 4+ cell grid");
    const ComparisonPlane plane = comparisonPlane(a);
    const double planeZ = plane.z, magnification = plane.magnification;
    const double zExact = a.focus.imageZExact;
    const double dzAim = a.lens.rearZ() - zExact;

    std::vector<ThickLensFilmError> out;
    for (int s = 0; s < o.filmRadii; ++s) {
        ThickLensFilmError e;
        e.filmRadius = minFilmRadius + (maxFilmRadius - minFilmRadius) * s / (o.filmRadii - 1);
        const double inf = std::numeric_limits<double>::infinity();
        e.maxErrorMm = e.centroidErrorMm = e.directionErrorRad = inf;
        const TraceResult chief = thickChiefRay(a, e.filmRadius);
        double xt, yt;
        if (!chief.ok() || !crossPlane(chief.ray, planeZ, xt, yt)) {
            out.push_back(e);
            continue;
        }
        const ExactFan fan = sampleExactRays(a.lens, zExact, e.filmRadius, o.pupilGrid);
        double worst = 0, sumX = 0, irradiance = 0;
        Vec3 sumDir{0, 0, 0};
        bool lost = false;
        for (std::size_t k = 0; k < fan.batch.size(); ++k) {
            if (fan.batch.blocked[k] != BlockReason::None) continue;
            const Ray ray = fan.batch.get(k);
            double xe, ye;
            if (!crossPlane(ray, planeZ, xe, ye)) {
                lost = true;
                continue;
            }
            ++e.exactRays;
            worst = std::max(worst, std::hypot(xe - xt, ye - yt));
            sumX += xe;
            sumDir = sumDir + Vec3{ray.direction.x, 0, ray.direction.z};
            irradiance += cos4(fan.cosines[k]);
        }
        if (e.exactRays > 0 && !lost) {
            const double scale = 1.0 / std::fabs(magnification);
            e.maxErrorMm = worst * scale;
            e.centroidErrorMm = std::fabs(sumX / e.exactRays - xt) * scale;
            const Vec3 mean = normalize(sumDir), thick = chief.ray.direction;
            e.directionErrorRad = std::acos(std::clamp(dot(mean, thick), -1.0, 1.0));
            // The grid's half counts twice (mirror symmetry about y = 0).
            const double exact = 2.0 * irradiance * fan.cellArea / (dzAim * dzAim);
            e.illuminationRatio = thickIrradiance(a, e.filmRadius, o.pupilGrid) / exact;
        }
        out.push_back(e);
    }
    return out;
}

}  // namespace lenslab
