// pbrt-v3's first exit-pupil box, as lenslab measures it for pbrt-v3's exposure (pbrt-v3's own
// procedure: a million quasi-random points), against a closed form (a bare stop) and against the
// true box of the passing region, found here by a grid and bisection to its edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "settings/LensAnalysis.h"
#include "prescription/LensSystem.h"
#include "firstorder/PbrtPupilBox.h"
#include "trace/ExactTrace.h"
#include "trace/RayBatch.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {


constexpr int kGrid = 512;
constexpr int kBisections = 30;

struct Bounds {
    double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
    bool empty() const { return !(minX <= maxX); }
};

class PassTest {
public:
    PassTest(const LensSystem& lens, double filmX, double filmZ) : lens_(lens), from_{filmX, 0, filmZ} {}
    bool operator()(double x, double y) const {
        const Ray ray{from_, normalize(Vec3{x, y, lens_.rearZ()} - from_)};
        return traceRay(lens_, ray, TraceDirection::FilmToScene).ok();
    }
    Ray rayTo(double x, double y) const { return {from_, normalize(Vec3{x, y, lens_.rearZ()} - from_)}; }

private:
    const LensSystem& lens_;
    Vec3 from_;
};

// The passing point's coordinate moved toward `outward` until the region's edge (bisection between
// the last passing grid point and the next one out).
double edge(const PassTest& passes, double x, double y, double dx, double dy) {
    double lo = 0, hi = 1;
    for (int i = 0; i < kBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        (passes(x + mid * dx, y + mid * dy) ? lo : hi) = mid;
    }
    return lo;
}

// The bounds of what passes from the film point (filmX, 0) within the square of half-width `half`:
// the grid's passing points, then, from each grid line that reaches an extreme, a bisection out to
// the region's edge (the line nearest the region's widest chord reaches farthest).
Bounds passingBounds(const LensSystem& lens, double filmX, double filmZ, double half) {
    const PassTest passes(lens, filmX, filmZ);
    const double cell = 2 * half / kGrid;
    const auto at = [&](int i) { return -half + (i + 0.5) * cell; };
    std::vector<int> rowMin(kGrid, kGrid), rowMax(kGrid, -1), colMin(kGrid, kGrid), colMax(kGrid, -1);
    RayBatch batch;
    batch.resize(kGrid);
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) batch.set(i, passes.rayTo(at(i), at(j)));
        traceBatch(lens, batch, TraceDirection::FilmToScene);
        for (int i = 0; i < kGrid; ++i) {
            if (batch.blocked[i] != BlockReason::None) continue;
            rowMin[j] = std::min(rowMin[j], i);
            rowMax[j] = std::max(rowMax[j], i);
            colMin[i] = std::min(colMin[i], j);
            colMax[i] = std::max(colMax[i], j);
        }
    }
    Bounds b;
    const int minI = *std::min_element(rowMin.begin(), rowMin.end()), maxI = *std::max_element(rowMax.begin(), rowMax.end());
    const int minJ = *std::min_element(colMin.begin(), colMin.end()), maxJ = *std::max_element(colMax.begin(), colMax.end());
    if (maxI < 0) return b;
    for (int k = 0; k < kGrid; ++k) {
        if (rowMin[k] == minI) b.minX = std::min(b.minX, at(minI) - cell * edge(passes, at(minI), at(k), -cell, 0));
        if (rowMax[k] == maxI) b.maxX = std::max(b.maxX, at(maxI) + cell * edge(passes, at(maxI), at(k), cell, 0));
        if (colMin[k] == minJ) b.minY = std::min(b.minY, at(minJ) - cell * edge(passes, at(k), at(minJ), 0, -cell));
        if (colMax[k] == maxJ) b.maxY = std::max(b.maxY, at(maxJ) + cell * edge(passes, at(k), at(maxJ), 0, cell));
    }
    return b;
}

// The true box, independently of pbrt-v3's sampling: the union of what passes from the segment's
// two ends (the pupil moves steadily along it), grown by pbrt-v3's step.
double trueBoxArea(const LensSystem& lens, double filmZ, double filmDiagonalMm) {
    const double half = 1.5 * lens.surfaces.back().apertureRadius;
    const Bounds centre = passingBounds(lens, 0.0, filmZ, half);
    const Bounds end = passingBounds(lens, filmDiagonalMm / 2 / 64, filmZ, half);
    const double grow = 2 * std::hypot(2 * half, 2 * half) / 1024;
    return (std::max(centre.maxX, end.maxX) - std::min(centre.minX, end.minX) + 2 * grow) *
           (std::max(centre.maxY, end.maxY) - std::min(centre.minY, end.minY) + 2 * grow);
}

LensAnalysis focusedAt4m(const char* name, double stopDiameter) {
    LensSettings s;
    s.stopDiameter = Setting{stopDiameter, "test"};
    s.focusDistance = Setting{4000, "test"};
    s.focusFromFilm = true;
    return analyzeLens(bundled(name), s);
}

}  // namespace

// A lone stop of radius a is the rear vertex's plane itself: from anywhere on the film the light
// passes through the disc of radius a, so the box is that disc's square, grown by pbrt-v3's step.
TEST(PbrtPupilBox, ABareStopsBoxIsItsSquareGrownByPbrtsStep) {
    LensSystem lens;
    Surface stop;
    stop.apertureRadius = 2;
    stop.isStop = true;
    lens.surfaces = {stop};
    lens.stopIndex = 0;
    const double grow = 2 * std::sqrt(2.0) * 6.0 / 1024;
    const double side = 4 + 2 * grow;
    // pbrt-v3's points stop short of the disc's edge by a small fraction of their spacing.
    EXPECT_NEAR(pbrtFirstPupilBoxArea(lens, -50, 35), side * side, 1e-3 * side * side);
}

// Within the true box and at most a few percent short of it: pbrt-v3's sample points come within a
// fraction of their spacing (1/1024 of the sampled square) of the region's edge, a larger share of a
// small pupil (wide.22mm at a 4 mm stop: 1.7%).
TEST(PbrtPupilBox, IsTheTrueBoxUpToPbrtsSampling) {
    const struct {
        const char* lens;
        double stop;
    } cases[] = {{"dgauss.50mm.dat", 10}, {"wide.22mm.dat", 4}, {"telephoto.250mm.dat", 20}, {"fisheye.10mm.dat", 3}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.lens);
        const LensAnalysis a = focusedAt4m(c.lens, c.stop);
        const double filmZ = a.focus.imageZExact;
        const double truth = trueBoxArea(a.lens, filmZ, 35), measured = pbrtFirstPupilBoxArea(a.lens, filmZ, 35);
        EXPECT_LE(measured, truth * (1 + 1e-6));
        EXPECT_GE(measured, truth * 0.97);
        RecordProperty(std::string(c.lens) + "_box_over_true", std::to_string(measured / truth));
    }
}

TEST(PbrtPupilBox, NoLightNoBox) {
    LensSystem lens = bundled("dgauss.50mm.dat");
    EXPECT_EQ(pbrtFirstPupilBoxArea(lens, lens.rearZ() + 10, 35), 0.0);  // a film in front of the rear vertex
}
