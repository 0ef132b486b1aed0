#include "analysis/RelativeIllumination.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "prescription/OpticsError.h"
#include "trace/RayBatch.h"

namespace lenslab {

namespace {

struct Box {
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

// Passing rays from one film point through a grid of aiming-plane points. A rotationally symmetric
// lens seen from (r, 0) is symmetric under y -> -y: its grids cover y >= 0 only, each cell standing
// for its mirror image too (half the rays; the same cells as the whole grid, whose row count is even).
class FilmPointProbe {
public:
    // Aims through the plane of surface `aim`'s vertex.
    FilmPointProbe(const LensSystem& lens, double filmZ, int aim)
        : lens_(lens), filmZ_(filmZ), aimZ_(lens.surfaces[aim].z), aimRadius_(lens.surfaces[aim].apertureRadius),
          halfPlane_(lens.isRotationallySymmetric()) {}

    double aimDistance() const { return aimZ_ - filmZ_; }
    double aimRadius() const { return aimRadius_; }  // the clear aperture at the aiming plane
    bool halfPlane() const { return halfPlane_; }

    // Traces the cell centres of an n x rows grid over `box` from (r, 0, filmZ); blocked[k] for cell k
    // (row-major).
    const std::vector<BlockReason>& trace(double r, const Box& box, int n, int rows) {
        batch_.resize(static_cast<std::size_t>(n) * rows);
        const double cx = (box.x1 - box.x0) / n, cy = (box.y1 - box.y0) / rows;
        const Vec3 from{r, 0, filmZ_};
        for (int j = 0; j < rows; ++j)
            for (int i = 0; i < n; ++i)
                batch_.set(static_cast<std::size_t>(j) * n + i,
                           {from, normalize(Vec3{box.x0 + (i + 0.5) * cx, box.y0 + (j + 0.5) * cy, aimZ_} - from)});
        traceBatch(lens_, batch_, TraceDirection::FilmToScene);
        return batch_.blocked;
    }

private:
    const LensSystem& lens_;
    double filmZ_, aimZ_, aimRadius_;
    bool halfPlane_;
    RayBatch batch_;
};

constexpr int kCoarse = 32;

// The bounding box of the passing points seen from film radius r, one coarse cell wider on every
// side; empty (x1 <= x0) when nothing passes. The search square grows while passing points touch
// its edge.
Box passingBounds(FilmPointProbe& probe, double r) {
    const bool half = probe.halfPlane();
    const int rows = half ? kCoarse / 2 : kCoarse;
    double extent = 1.5 * probe.aimRadius();
    for (int grow = 0; grow < 5; ++grow, extent *= 2) {
        const Box square{-extent, extent, half ? 0.0 : -extent, extent};
        const std::vector<BlockReason>& blocked = probe.trace(r, square, kCoarse, rows);
        const double cell = 2 * extent / kCoarse;
        int i0 = kCoarse, i1 = -1, j0 = rows, j1 = -1;
        for (int j = 0; j < rows; ++j)
            for (int i = 0; i < kCoarse; ++i)
                if (blocked[static_cast<std::size_t>(j) * kCoarse + i] == BlockReason::None) {
                    i0 = std::min(i0, i), i1 = std::max(i1, i);
                    j0 = std::min(j0, j), j1 = std::max(j1, j);
                }
        if (i1 < 0) return {};
        const bool touchesEdge = i0 == 0 || (!half && j0 == 0) || i1 == kCoarse - 1 || j1 == rows - 1;
        if (touchesEdge && grow < 4) continue;
        const double top = square.y0 + (j1 + 2) * cell;
        return {-extent + (i0 - 1) * cell, -extent + (i1 + 2) * cell, half ? -top : square.y0 + (j0 - 1) * cell, top};
    }
    return {};
}

struct Flux {
    double area = 0;      // mm^2 of the aiming plane whose rays pass
    double weighted = 0;  // the same area weighted by cos^4(theta)
};

Flux passingFlux(FilmPointProbe& probe, double r, int grid) {
    Box box = passingBounds(probe, r);
    Flux flux;
    if (!(box.x1 > box.x0)) return flux;
    const double cx = (box.x1 - box.x0) / grid, cy = (box.y1 - box.y0) / grid;
    int rows = grid;
    if (probe.halfPlane()) {  // the upper half of the symmetric box, each cell counted twice
        box.y0 = 0;
        rows = grid / 2;
    }
    const double cellArea = cx * cy * (probe.halfPlane() ? 2 : 1);
    const std::vector<BlockReason>& blocked = probe.trace(r, box, grid, rows);
    const double z2 = probe.aimDistance() * probe.aimDistance();
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < grid; ++i) {
            if (blocked[static_cast<std::size_t>(j) * grid + i] != BlockReason::None) continue;
            const double dx = box.x0 + (i + 0.5) * cx - r, dy = box.y0 + (j + 0.5) * cy;
            const double cos2 = z2 / (dx * dx + dy * dy + z2);
            flux.area += cellArea;
            flux.weighted += cellArea * cos2 * cos2;
        }
    return flux;
}

void requireFilmBehindLens(const LensSystem& lens, double filmZ) {
    if (!(filmZ < lens.rearZ()))
        throw OpticsError("relative illumination: the film must lie behind the rear vertex");
}

}  // namespace

std::vector<IlluminationSample> relativeIllumination(const LensSystem& lens, double filmZ, double maxFilmRadius,
                                                     const RelativeIlluminationOptions& options) {
    requireFilmBehindLens(lens, filmZ);
    if (options.filmRadii < 2 || options.grid < 8 || options.grid % 2)
        throw OpticsError("relative illumination: need at least 2 film radii and an even grid of at least 8 x 8");
    // Rays are aimed through points of the rear vertex's plane. A cover glass just before the film
    // brings that plane so close that the passing region is smaller than a search cell: then aim
    // through the front vertex's plane, where it is about as large as the lens. (The ratio of
    // fluxes does not depend on the plane: both film points are measured on the same one.)
    FilmPointProbe nearProbe(lens, filmZ, int(lens.surfaces.size()) - 1), farProbe(lens, filmZ, 0);
    FilmPointProbe* probeUsed = &nearProbe;
    Flux centre = passingFlux(nearProbe, 0.0, options.grid);
    if (!(centre.weighted > 0)) {
        probeUsed = &farProbe;
        centre = passingFlux(farProbe, 0.0, options.grid);
    }
    if (!(centre.weighted > 0)) throw OpticsError("relative illumination: no ray from the film centre passes the lens");
    // The film radii are independent: traced side by side, each with a probe of its own.
    const int aimSurface = probeUsed == &nearProbe ? int(lens.surfaces.size()) - 1 : 0;
    std::vector<IlluminationSample> samples(options.filmRadii);
    tbb::parallel_for(0, options.filmRadii, [&](int k) {
        const double r = maxFilmRadius * k / (options.filmRadii - 1);
        FilmPointProbe probe(lens, filmZ, aimSurface);
        const Flux f = k == 0 ? centre : passingFlux(probe, r, options.grid);
        samples[k] = {r, f.area / centre.area, f.weighted / centre.weighted};
    });
    return samples;
}

double imageCircleRadius(const LensSystem& lens, double filmZ, double limit) {
    requireFilmBehindLens(lens, filmZ);
    // Aimed through the rear vertex's plane, else the front vertex's, as relativeIllumination aims
    // (a cover glass at the film, a mirror lens whose rear plane no passing ray crosses near the axis).
    FilmPointProbe nearProbe(lens, filmZ, int(lens.surfaces.size()) - 1), farProbe(lens, filmZ, 0);
    FilmPointProbe* probe = &nearProbe;
    auto anyPasses = [&](double r) {
        const Box b = passingBounds(*probe, r);
        return b.x1 > b.x0;
    };
    if (!anyPasses(0.0)) probe = &farProbe;
    if (!anyPasses(0.0)) return 0.0;
    if (anyPasses(limit)) return limit;
    double lo = 0, hi = limit;
    for (int it = 0; it < 30; ++it) {
        const double mid = 0.5 * (lo + hi);
        (anyPasses(mid) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace lenslab
