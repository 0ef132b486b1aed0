#include "firstorder/ExitPupilBounds.h"

#include <algorithm>
#include <cmath>

#include "prescription/OpticsError.h"
#include "prescription/Pi.h"
#include "trace/RayBatch.h"

namespace lenslab {

namespace {

constexpr int kMaxVertices = 256;

// Which aiming-plane points (x, y) pass the lens from the film point (r, 0, filmZ).
class PassTest {
public:
    PassTest(LensSystem lens, double filmZ, double aimZ) : lens_(std::move(lens)), filmZ_(filmZ), aimZ_(aimZ) {}

    std::vector<bool> operator()(double r, const std::vector<double>& xs, const std::vector<double>& ys) {
        batch_.resize(xs.size());
        for (std::size_t i = 0; i < xs.size(); ++i) {
            const Vec3 from{r, 0, filmZ_};
            batch_.set(i, {from, normalize(Vec3{xs[i], ys[i], aimZ_} - from)});
        }
        traceBatch(lens_, batch_, TraceDirection::FilmToScene);
        std::vector<bool> pass(xs.size());
        for (std::size_t i = 0; i < xs.size(); ++i) pass[i] = batch_.blocked[i] == BlockReason::None;
        return pass;
    }

private:
    LensSystem lens_;
    double filmZ_, aimZ_;
    RayBatch batch_;
};

struct GridScan {
    bool any = false;
    bool touchesEdge = false;
    double centreX = 0;
    double reach = 0;  // farthest passing point from the centre
};

// Passing points of a grid over the half-disc y >= 0 of radius `extent` (the region is symmetric).
GridScan scanGrid(PassTest& passes, double r, double extent, int cells) {
    std::vector<double> xs, ys;
    const double cell = 2.0 * extent / cells;
    for (int j = 0; j < cells / 2; ++j)
        for (int i = 0; i < cells; ++i) {
            xs.push_back(-extent + (i + 0.5) * cell);
            ys.push_back((j + 0.5) * cell);
        }
    const std::vector<bool> pass = passes(r, xs, ys);
    GridScan g;
    double sumX = 0;
    int count = 0;
    for (std::size_t k = 0; k < pass.size(); ++k) {
        if (!pass[k]) continue;
        sumX += xs[k];
        ++count;
        if (std::hypot(xs[k], ys[k]) > extent - 1.5 * cell) g.touchesEdge = true;
    }
    if (count == 0) return g;
    g.any = true;
    g.centreX = sumX / count;
    for (std::size_t k = 0; k < pass.size(); ++k)
        if (pass[k]) g.reach = std::max(g.reach, std::hypot(xs[k] - g.centreX, ys[k]) + cell);
    return g;
}

// The outermost passing distance along each of the half-polygon's directions: a scan inward from
// beyond the grid's reach, then bisection of the last step.
std::vector<double> boundaryDistances(PassTest& passes, double r, const GridScan& g, int vertices) {
    constexpr int kSteps = 64, kBisections = 16;
    const int half = vertices / 2 + 1;
    std::vector<double> cosA(half), sinA(half);
    for (int k = 0; k < half; ++k) {
        cosA[k] = std::cos(2.0 * kPi * k / vertices);
        sinA[k] = std::sin(2.0 * kPi * k / vertices);
    }
    const double start = g.reach * 1.25;
    std::vector<double> xs, ys;
    for (int k = 0; k < half; ++k)
        for (int s = 0; s < kSteps; ++s) {
            const double rho = start * (1.0 - static_cast<double>(s) / kSteps);
            xs.push_back(g.centreX + rho * cosA[k]);
            ys.push_back(rho * sinA[k]);
        }
    const std::vector<bool> pass = passes(r, xs, ys);
    std::vector<double> lo(half, 0.0), hi(half, 0.0);
    for (int k = 0; k < half; ++k) {
        int s = 0;
        while (s < kSteps && !pass[k * kSteps + s]) ++s;
        lo[k] = s < kSteps ? start * (1.0 - static_cast<double>(s) / kSteps) : 0.0;
        hi[k] = s > 0 ? start * (1.0 - static_cast<double>(s - 1) / kSteps) : start;
    }
    for (int it = 0; it < kBisections; ++it) {
        xs.clear();
        ys.clear();
        for (int k = 0; k < half; ++k) {
            const double mid = 0.5 * (lo[k] + hi[k]);
            xs.push_back(g.centreX + mid * cosA[k]);
            ys.push_back(mid * sinA[k]);
        }
        const std::vector<bool> midPass = passes(r, xs, ys);
        for (int k = 0; k < half; ++k) {
            if (lo[k] == 0.0) continue;  // nothing passed along this direction
            (midPass[k] ? lo[k] : hi[k]) = 0.5 * (lo[k] + hi[k]);
        }
    }
    return hi;  // the failing side of the bisection: never inside the passing region
}

// The boundary distances at another wavelength, direction by direction, from `own` (measured at
// the lens's own wavelength, the failing side): a region shifts only slightly with the wavelength,
// so a bisection between half and one and a half times the own distance finds the other's at a
// small fraction of a full measurement's rays. A direction where the other region does not pass at
// half the own distance keeps the own one (no such lens seen); one where it passes beyond one and a
// half searches outward.
std::vector<double> boundaryAtWavelength(PassTest& passes, double r, double centreX, int vertices,
                                         const std::vector<double>& own) {
    constexpr int kBisections = 10, kGrowths = 4;
    const int count = static_cast<int>(own.size());
    std::vector<double> cosA(count), sinA(count), lo(count), hi(count);
    for (int k = 0; k < count; ++k) {
        cosA[k] = std::cos(2.0 * kPi * k / vertices);
        sinA[k] = std::sin(2.0 * kPi * k / vertices);
        lo[k] = 0.5 * own[k];
        hi[k] = 1.5 * own[k];
    }
    std::vector<double> xs(count), ys(count);
    const auto test = [&](const std::vector<double>& rho) {
        for (int k = 0; k < count; ++k) {
            xs[k] = centreX + rho[k] * cosA[k];
            ys[k] = rho[k] * sinA[k];
        }
        return passes(r, xs, ys);
    };
    const std::vector<bool> inner = test(lo);
    for (int grow = 0; grow < kGrowths; ++grow) {
        const std::vector<bool> outer = test(hi);
        bool any = false;
        for (int k = 0; k < count; ++k)
            if (outer[k] && own[k] > 0) lo[k] = hi[k], hi[k] *= 2, any = true;
        if (!any) break;
    }
    for (int it = 0; it < kBisections; ++it) {
        std::vector<double> mid(count);
        for (int k = 0; k < count; ++k) mid[k] = 0.5 * (lo[k] + hi[k]);
        const std::vector<bool> midPass = test(mid);
        for (int k = 0; k < count; ++k) (midPass[k] ? lo[k] : hi[k]) = mid[k];
    }
    std::vector<double> half(count);
    for (int k = 0; k < count; ++k) half[k] = own[k] > 0 && inner[k] ? hi[k] : own[k];
    return half;
}

// A film radius's region at the lens's own wavelength: its centre and half-polygon (the failing
// side of each direction's bisection; nothing when no ray passes).
struct OwnRegion {
    bool any = false;
    double centreX = 0;
    std::vector<double> half;
};

OwnRegion measureRegion(PassTest& passes, double r, double aimRadius, int vertices) {
    double extent = 1.5 * aimRadius;
    GridScan g = scanGrid(passes, r, extent, 64);
    for (int grow = 0; grow < 4 && g.touchesEdge; ++grow) {
        extent *= 2;
        g = scanGrid(passes, r, extent, 64);
    }
    if (!g.any) g = scanGrid(passes, r, extent, 256);  // a sliver the coarse grid missed
    if (!g.any) return {};
    return {true, g.centreX, boundaryDistances(passes, r, g, vertices)};
}

// The plane camera rays are aimed through: the rear vertex's, unless a cover glass just before the
// film brings it so close that the film centre's passing region is smaller than a cell of the
// search grid (the Sony 55 mm's, 1 mm from the film: 0.3 mm across against 1 mm cells, so that
// every film radius fell back to the fine grid, 16 times the rays); then the front vertex's, where
// the region is about as large as the lens (as relativeIllumination aims). Decided at the film
// centre, so that a crop window's regions stay the whole frame's.
double aimingPlaneZ(const LensSystem& lens, double filmZ) {
    PassTest rear(lens, filmZ, lens.rearZ());
    if (scanGrid(rear, 0.0, 1.5 * lens.surfaces.back().apertureRadius, 64).any) return lens.rearZ();
    PassTest front(lens, filmZ, lens.frontZ());
    return scanGrid(front, 0.0, 1.5 * lens.surfaces.front().apertureRadius, 64).any ? lens.frontZ() : lens.rearZ();
}

// The clear aperture of the surface whose vertex plane is the aiming plane: the search grid's scale.
double aimingRadius(const LensSystem& lens, double aimZ) {
    return (aimZ == lens.rearZ() ? lens.surfaces.back() : lens.surfaces.front()).apertureRadius;
}

// Where film radius r falls between the measured radii: rows i and j = i + 1 (or i at the ends),
// weight f of row j.
struct RadiusWeight {
    int i = 0, j = 0;
    double f = 0;
};

RadiusWeight radiusWeight(const ExitPupilBounds& b, double r) {
    const int last = b.radiusCount() - 1;
    const double t = b.radiusStep > 0 ? std::clamp(r / b.radiusStep - b.firstRadius, 0.0, double(last)) : 0.0;
    RadiusWeight w;
    w.i = std::min(static_cast<int>(t), std::max(last - 1, 0));
    w.f = last > 0 ? t - w.i : 0.0;
    w.j = std::min(w.i + 1, last);
    return w;
}

// Fills fanAreas, vertexX and vertexY (ExitPupilBounds.h).
void tabulateFans(ExitPupilBounds& b) {
    const int n = b.vertices, last = b.radiusCount() - 1, pairs = std::max(last, 1);
    const double halfSin = 0.5 * std::sin(2.0 * kPi / n);
    b.fanAreas.assign(static_cast<std::size_t>(pairs) * (n + 1) * 3, 0.0);
    for (int i = 0; i < pairs; ++i) {
        const double* a = &b.rho[static_cast<std::size_t>(i) * n];
        const double* c = &b.rho[static_cast<std::size_t>(std::min(i + 1, last)) * n];
        double* cum = &b.fanAreas[static_cast<std::size_t>(i) * (n + 1) * 3];
        for (int k = 0; k < n; ++k) {
            const int k1 = (k + 1) % n;
            cum[3 * (k + 1)] = cum[3 * k] + halfSin * a[k] * a[k1];
            cum[3 * (k + 1) + 1] = cum[3 * k + 1] + halfSin * (a[k] * c[k1] + c[k] * a[k1]);
            cum[3 * (k + 1) + 2] = cum[3 * k + 2] + halfSin * c[k] * c[k1];
        }
    }
    b.vertexX.resize(n + 1);
    b.vertexY.resize(n + 1);
    for (int k = 0; k <= n; ++k) {
        b.vertexX[k] = std::cos(2.0 * kPi * k / n);
        b.vertexY[k] = std::sin(2.0 * kPi * k / n);
    }
}

}  // namespace

ExitPupilBounds computeExitPupilBounds(const LensSystem& lens, double filmZ, double maxFilmRadius,
                                       const ExitPupilBoundsOptions& options) {
    if (options.filmRadii < 2) throw OpticsError("exit pupil bounds: need at least 2 film radii");
    if (!(maxFilmRadius > 0)) throw OpticsError("exit pupil bounds: the film needs a positive size");
    return computeExitPupilBounds(lens, filmZ, maxFilmRadius / (options.filmRadii - 1), 0, options.filmRadii - 1,
                                  options);
}

namespace {

void checkOptions(double filmZ, const LensSystem& lens, double radiusStep, int firstRadius, int lastRadius,
                  const ExitPupilBoundsOptions& options) {
    if (options.vertices < 8 || options.vertices > kMaxVertices || options.vertices % 2 != 0)
        throw OpticsError("exit pupil bounds: vertices must be even, 8 to 256");
    if (!(radiusStep > 0) || firstRadius < 0 || lastRadius <= firstRadius)
        throw OpticsError("exit pupil bounds: need a positive radius step and at least 2 film radii");
    if (!(filmZ < lens.rearZ())) throw OpticsError("exit pupil bounds: the film must lie behind the rear vertex");
}

// Bounds with no regions yet: the radii and the aiming plane.
ExitPupilBounds emptyBounds(const LensSystem& lens, double filmZ, double radiusStep, int firstRadius, int lastRadius,
                            int vertices) {
    ExitPupilBounds b;
    b.filmZ = filmZ;
    b.aimZ = aimingPlaneZ(lens, filmZ);
    b.radiusStep = radiusStep;
    b.firstRadius = firstRadius;
    b.vertices = vertices;
    const int count = lastRadius - firstRadius + 1;
    b.centreX.assign(count, 0.0);
    b.rho.assign(static_cast<std::size_t>(count) * vertices, 0.0);
    return b;
}

// Radius i's polygon from a half-polygon, mirrored about y = 0 and widened by the margin.
void setRegion(ExitPupilBounds& b, int i, double centreX, const std::vector<double>& half, double margin) {
    const int n = b.vertices;
    b.centreX[i] = centreX;
    for (int k = 0; k < n; ++k) {
        const int m = k <= n / 2 ? k : n - k;
        b.rho[static_cast<std::size_t>(i) * n + k] = half[m] * (1.0 + margin);
    }
}

// Measures every radius's own region, reporting each to `use(i, r, region)`, with the options'
// progress and cancel.
template <class Use>
void measureRegions(const LensSystem& lens, const ExitPupilBounds& b, const ExitPupilBoundsOptions& options, Use use) {
    PassTest passes(lens, b.filmZ, b.aimZ);
    const double aimRadius = aimingRadius(lens, b.aimZ);
    const int count = b.radiusCount();
    for (int i = 0; i < count; ++i) {
        if (options.progress && i > 0) options.progress(double(i) / count);
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) throw SetupCancelled();
        const double r = (b.firstRadius + i) * b.radiusStep;
        const OwnRegion region = measureRegion(passes, r, aimRadius, b.vertices);
        if (region.any) use(i, r, region);
    }
    if (options.progress) options.progress(1.0);
}

}  // namespace

ExitPupilBounds computeExitPupilBounds(const LensSystem& lens, double filmZ, double radiusStep, int firstRadius,
                                       int lastRadius, const ExitPupilBoundsOptions& options) {
    checkOptions(filmZ, lens, radiusStep, firstRadius, lastRadius, options);
    ExitPupilBounds b = emptyBounds(lens, filmZ, radiusStep, firstRadius, lastRadius, options.vertices);
    measureRegions(lens, b, options, [&](int i, double, const OwnRegion& region) {
        setRegion(b, i, region.centreX, region.half, options.margin);
    });
    tabulateFans(b);
    return b;
}

SpectralExitPupilBounds computeSpectralExitPupilBounds(const LensSystem& lens, double filmZ, double radiusStep,
                                                       int firstRadius, int lastRadius,
                                                       const std::vector<double>& edgesNm,
                                                       const ExitPupilBoundsOptions& options) {
    checkOptions(filmZ, lens, radiusStep, firstRadius, lastRadius, options);
    if (edgesNm.size() < 2 || !std::is_sorted(edgesNm.begin(), edgesNm.end()))
        throw OpticsError("spectral exit pupil bounds: need at least two wavelengths, ascending");
    SpectralExitPupilBounds s;
    s.edgesNm = edgesNm;
    const ExitPupilBounds empty = emptyBounds(lens, filmZ, radiusStep, firstRadius, lastRadius, options.vertices);
    s.bands.assign(edgesNm.size() - 1, empty);
    std::vector<PassTest> atEdges;
    for (double nm : edgesNm) atEdges.emplace_back(atWavelength(lens, nm), filmZ, empty.aimZ);
    measureRegions(lens, empty, options, [&](int i, double r, const OwnRegion& region) {
        std::vector<std::vector<double>> edge;
        for (PassTest& p : atEdges) edge.push_back(boundaryAtWavelength(p, r, region.centreX, options.vertices, region.half));
        // A band holding the lens's own wavelength also holds its measured region.
        for (std::size_t band = 0; band + 1 < edge.size(); ++band) {
            const bool holdsOwn = lens.wavelength >= edgesNm[band] && lens.wavelength <= edgesNm[band + 1];
            std::vector<double> half(region.half.size());
            for (std::size_t k = 0; k < half.size(); ++k)
                half[k] = std::max({edge[band][k], edge[band + 1][k], holdsOwn ? region.half[k] : 0.0});
            setRegion(s.bands[band], i, region.centreX, half, options.margin);
        }
    });
    for (ExitPupilBounds& b : s.bands) tabulateFans(b);
    return s;
}

std::size_t SpectralExitPupilBounds::bandOf(double nm) const {
    const auto above = std::upper_bound(edgesNm.begin() + 1, edgesNm.end() - 1, nm);
    return std::size_t(above - edgesNm.begin()) - 1;
}

void sampleSpectralExitPupils(const SpectralExitPupilBounds& bounds, std::size_t count, const double* filmX,
                              const double* filmY, const double* u1, const double* u2, const double* nm,
                              PupilSampleBatch& out) {
    thread_local std::vector<std::size_t> of, start;
    thread_local std::vector<std::uint8_t> bandOfSample;
    thread_local std::vector<double> fx, fy, v1, v2;
    thread_local PupilSampleBatch part;
    out.resize(count);
    // The samples sorted by band (a counting sort), each band sampled as one batch.
    const std::size_t bands = bounds.bands.size();
    bandOfSample.resize(count);
    start.assign(bands + 1, 0);
    for (std::size_t s = 0; s < count; ++s) ++start[(bandOfSample[s] = std::uint8_t(bounds.bandOf(nm[s]))) + 1];
    for (std::size_t band = 0; band < bands; ++band) start[band + 1] += start[band];
    of.resize(count);
    {
        std::vector<std::size_t> next(start.begin(), start.end() - 1);
        for (std::size_t s = 0; s < count; ++s) of[next[bandOfSample[s]]++] = s;
    }
    for (std::size_t band = 0; band < bands; ++band) {
        const std::size_t* members = of.data() + start[band];
        const std::size_t size = start[band + 1] - start[band];
        if (size == 0) continue;
        for (auto* v : {&fx, &fy, &v1, &v2}) v->resize(size);
        for (std::size_t k = 0; k < size; ++k) {
            fx[k] = filmX[members[k]];
            fy[k] = filmY[members[k]];
            v1[k] = u1[members[k]];
            v2[k] = u2[members[k]];
        }
        sampleExitPupils(bounds.bands[band], size, fx.data(), fy.data(), v1.data(), v2.data(), part);
        for (std::size_t k = 0; k < size; ++k) {
            out.x[members[k]] = part.x[k];
            out.y[members[k]] = part.y[k];
            out.area[members[k]] = part.area[k];
        }
    }
}

namespace {

// The fan's area up to a vertex at the weight f between two radii, from the tabulated sums at
// fans[at], fans[at + 1], fans[at + 2] (ExitPupilBounds::fanAreas).
inline double fanArea(const double* fans, int at, double f) {
    return (1 - f) * (1 - f) * fans[at] + f * (1 - f) * fans[at + 1] + f * f * fans[at + 2];
}

}  // namespace

void sampleExitPupils(const ExitPupilBounds& b, std::size_t count, const double* filmX, const double* filmY,
                      const double* u1, const double* u2, PupilSampleBatch& out) {
    out.resize(count);
    const int n = b.vertices, last = b.radiusCount() - 1, lastPair = std::max(last - 1, 0);
    const double step = b.radiusStep, first = b.firstRadius;
    const double* fans = b.fanAreas.data();
    const double* rho = b.rho.data();
    const double* centreX = b.centreX.data();
    const double* vertexX = b.vertexX.data();
    const double* vertexY = b.vertexY.data();
    const int stride = (n + 1) * 3;
    double* r = out.radius.data();
    double* f = out.weight.data();
    double* target = out.target.data();
    double* area = out.area.data();
    int* row = out.row.data();
    int* k = out.vertex.data();
    // Each stage is one loop over the samples (structure of arrays, int offsets so that table reads
    // become gathers), which the compiler vectorises; radiusWeight's arithmetic, written out.
#pragma GCC ivdep
    for (std::size_t s = 0; s < count; ++s) {
        r[s] = std::sqrt(filmX[s] * filmX[s] + filmY[s] * filmY[s]);  // mm: no overflow, cheaper than hypot
        const double t = step > 0 ? std::clamp(r[s] / step - first, 0.0, double(last)) : 0.0;
        const int i = std::min(static_cast<int>(t), lastPair);
        row[s] = i;
        f[s] = last > 0 ? t - i : 0.0;
        area[s] = fanArea(fans, i * stride + n * 3, f[s]);
        target[s] = u1[s] * area[s];
        k[s] = 0;
    }
    // The fan triangle holding target, areaTo(k) <= target < areaTo(k + 1), by a search whose steps
    // depend on n alone: one pass over the samples per halving.
    for (int len = n; len > 1;) {
        const int half = len / 2;
#pragma GCC ivdep
        for (std::size_t s = 0; s < count; ++s)
            k[s] = fanArea(fans, row[s] * stride + (k[s] + half) * 3, f[s]) <= target[s] ? k[s] + half : k[s];
        len -= half;
    }
    const int lastRow = std::max(b.radiusCount() - 1, 0);
#pragma GCC ivdep
    for (std::size_t s = 0; s < count; ++s) {
        const int i = row[s], j = std::min(i + 1, lastRow), v0 = k[s], v1 = v0 + 1 == n ? 0 : v0 + 1;
        const double fs = f[s], below = fanArea(fans, i * stride + v0 * 3, fs);
        const double tri = fanArea(fans, i * stride + v0 * 3 + 3, fs) - below;
        const double v = tri > 0 ? std::clamp((target[s] - below) / tri, 0.0, 1.0) : 0.5;
        const double rho0 = (1 - fs) * rho[i * n + v0] + fs * rho[j * n + v0];
        const double rho1 = (1 - fs) * rho[i * n + v1] + fs * rho[j * n + v1];
        // Uniform over the fan triangle (centre, vertex k, vertex k+1).
        const double s1 = std::sqrt(v), w2 = u2[s];
        const double lx = s1 * ((1 - w2) * rho0 * vertexX[v0] + w2 * rho1 * vertexX[v0 + 1]);
        const double ly = s1 * ((1 - w2) * rho0 * vertexY[v0] + w2 * rho1 * vertexY[v0 + 1]);
        const double x = (1 - fs) * centreX[i] + fs * centreX[j] + lx;
        const double rs = r[s], c = rs > 0 ? filmX[s] / rs : 1.0, sn = rs > 0 ? filmY[s] / rs : 0.0;
        out.x[s] = x * c - ly * sn;
        out.y[s] = x * sn + ly * c;
    }
}

PupilSample sampleExitPupil(const ExitPupilBounds& b, double filmX, double filmY, double u1, double u2) {
    thread_local PupilSampleBatch one;
    sampleExitPupils(b, 1, &filmX, &filmY, &u1, &u2, one);
    PupilSample s;
    s.area = one.area[0];
    if (s.area > 0) s.point = {one.x[0], one.y[0], b.aimZ};
    return s;
}

bool insideExitPupilBounds(const ExitPupilBounds& b, double filmX, double filmY, double x, double y) {
    const double r = std::sqrt(filmX * filmX + filmY * filmY);  // mm: no overflow, cheaper than hypot
    const auto [i, j, f] = radiusWeight(b, r);
    const int n = b.vertices;
    const double c = r > 0 ? filmX / r : 1.0, sn = r > 0 ? filmY / r : 0.0;
    const double lx = x * c + y * sn - ((1 - f) * b.centreX[i] + f * b.centreX[j]), ly = -x * sn + y * c;
    // The fan sector holding the point: between vertex directions k and k + 1 (b.vertexX/Y, the
    // directions sampling uses), found from its angle and settled by the sides of those directions.
    double angle = std::atan2(ly, lx);
    if (angle < 0) angle += 2.0 * kPi;
    int k = std::min(static_cast<int>(angle / (2.0 * kPi) * n), n - 1);
    const auto leftOf = [&](int v) { return b.vertexX[v] * ly - b.vertexY[v] * lx >= 0; };
    if (!leftOf(k)) k = (k + n - 1) % n;
    else if (leftOf(k + 1)) k = (k + 1) % n;
    const int k1 = (k + 1) % n;
    const double rho0 = (1 - f) * b.rho[std::size_t(i) * n + k] + f * b.rho[std::size_t(j) * n + k];
    const double rho1 = (1 - f) * b.rho[std::size_t(i) * n + k1] + f * b.rho[std::size_t(j) * n + k1];
    const double x0 = rho0 * b.vertexX[k], y0 = rho0 * b.vertexY[k];
    const double x1 = rho1 * b.vertexX[k + 1], y1 = rho1 * b.vertexY[k + 1];
    // Inside the fan triangle: on the centre's side of the edge from vertex k to vertex k+1.
    return (x1 - x0) * (ly - y0) - (y1 - y0) * (lx - x0) >= 0;
}

}  // namespace lenslab
