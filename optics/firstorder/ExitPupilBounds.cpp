#include "firstorder/ExitPupilBounds.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "prescription/OpticsError.h"
#include "trace/RayBatch.h"

namespace lenslab {

namespace {

constexpr double kPi = 3.14159265358979323846;
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

// Widens the boundary distances `half` (measured for the lens's own wavelength, the failing side)
// to where the lens at another wavelength still passes rays, direction by direction: a region
// shifts only slightly with the wavelength, so a bisection between the own boundary and a quarter
// beyond it finds the other's at a small fraction of a full measurement's rays.
void widenForWavelength(PassTest& passes, double r, double centreX, int vertices, std::vector<double>& half) {
    constexpr int kBisections = 10;
    const int count = static_cast<int>(half.size());
    std::vector<double> cosA(count), sinA(count), lo(half), hi(count);
    for (int k = 0; k < count; ++k) {
        cosA[k] = std::cos(2.0 * kPi * k / vertices);
        sinA[k] = std::sin(2.0 * kPi * k / vertices);
        hi[k] = 1.25 * half[k];
    }
    std::vector<double> xs(count), ys(count);
    const auto test = [&](const std::vector<double>& rho) {
        for (int k = 0; k < count; ++k) {
            xs[k] = centreX + rho[k] * cosA[k];
            ys[k] = rho[k] * sinA[k];
        }
        return passes(r, xs, ys);
    };
    const std::vector<bool> beyondOwn = test(lo);
    for (int it = 0; it < kBisections; ++it) {
        std::vector<double> mid(count);
        for (int k = 0; k < count; ++k) mid[k] = 0.5 * (lo[k] + hi[k]);
        const std::vector<bool> midPass = test(mid);
        for (int k = 0; k < count; ++k) (midPass[k] ? lo[k] : hi[k]) = mid[k];
    }
    for (int k = 0; k < count; ++k)
        if (beyondOwn[k] && half[k] > 0) half[k] = hi[k];
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

// The polygon seen from film radius r, interpolated between the measured radii (full circle).
struct Polygon {
    double centreX = 0;
    int n = 0;
    std::array<double, kMaxVertices> rho{};
};

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

Polygon polygonAt(const ExitPupilBounds& b, double r) {
    Polygon p;
    p.n = b.vertices;
    const auto [i, j, f] = radiusWeight(b, r);
    p.centreX = (1 - f) * b.centreX[i] + f * b.centreX[j];
    for (int k = 0; k < p.n; ++k)
        p.rho[k] = (1 - f) * b.rho[i * p.n + k] + f * b.rho[j * p.n + k];
    return p;
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

ExitPupilBounds computeExitPupilBounds(const LensSystem& lens, double filmZ, double radiusStep, int firstRadius,
                                       int lastRadius, const ExitPupilBoundsOptions& options) {
    if (options.vertices < 8 || options.vertices > kMaxVertices || options.vertices % 2 != 0)
        throw OpticsError("exit pupil bounds: vertices must be even, 8 to 256");
    if (!(radiusStep > 0) || firstRadius < 0 || lastRadius <= firstRadius)
        throw OpticsError("exit pupil bounds: need a positive radius step and at least 2 film radii");
    if (!(filmZ < lens.rearZ())) throw OpticsError("exit pupil bounds: the film must lie behind the rear vertex");
    ExitPupilBounds b;
    b.filmZ = filmZ;
    b.aimZ = aimingPlaneZ(lens, filmZ);
    b.radiusStep = radiusStep;
    b.firstRadius = firstRadius;
    b.vertices = options.vertices;
    const int n = options.vertices, count = lastRadius - firstRadius + 1;
    b.centreX.assign(count, 0.0);
    b.rho.assign(static_cast<std::size_t>(count) * n, 0.0);
    PassTest passes(lens, filmZ, b.aimZ);
    std::vector<PassTest> otherWavelengths;
    for (double nm : options.wavelengthsNm) otherWavelengths.emplace_back(atWavelength(lens, nm), filmZ, b.aimZ);
    const double aimRadius = aimingRadius(lens, b.aimZ);
    for (int i = 0; i < count; ++i) {
        if (options.progress && i > 0) options.progress(double(i) / count);
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) throw SetupCancelled();
        const double r = (firstRadius + i) * radiusStep;
        double extent = 1.5 * aimRadius;
        GridScan g = scanGrid(passes, r, extent, 64);
        for (int grow = 0; grow < 4 && g.touchesEdge; ++grow) {
            extent *= 2;
            g = scanGrid(passes, r, extent, 64);
        }
        if (!g.any) g = scanGrid(passes, r, extent, 256);  // a sliver the coarse grid missed
        if (!g.any) continue;
        std::vector<double> half = boundaryDistances(passes, r, g, n);
        for (PassTest& other : otherWavelengths) widenForWavelength(other, r, g.centreX, n, half);
        b.centreX[i] = g.centreX;
        for (int k = 0; k < n; ++k) {
            const int m = k <= n / 2 ? k : n - k;  // mirror image about y = 0
            b.rho[static_cast<std::size_t>(i) * n + k] = half[m] * (1.0 + options.margin);
        }
    }
    tabulateFans(b);
    if (options.progress) options.progress(1.0);
    return b;
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
    const Polygon p = polygonAt(b, r);
    const double c = r > 0 ? filmX / r : 1.0, sn = r > 0 ? filmY / r : 0.0;
    const double lx = x * c + y * sn - p.centreX, ly = -x * sn + y * c;
    double angle = std::atan2(ly, lx);
    if (angle < 0) angle += 2.0 * kPi;
    const int k = std::min(static_cast<int>(angle / (2.0 * kPi) * p.n), p.n - 1);
    const double a0 = 2.0 * kPi * k / p.n, a1 = 2.0 * kPi * (k + 1) / p.n;
    const double x0 = p.rho[k] * std::cos(a0), y0 = p.rho[k] * std::sin(a0);
    const double x1 = p.rho[(k + 1) % p.n] * std::cos(a1), y1 = p.rho[(k + 1) % p.n] * std::sin(a1);
    // Inside the fan triangle: on the centre's side of the edge from vertex k to vertex k+1.
    return (x1 - x0) * (ly - y0) - (y1 - y0) * (lx - x0) >= 0;
}

}  // namespace lenslab
