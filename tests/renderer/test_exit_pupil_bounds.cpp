// The exit-pupil bounds must hold every ray that passes (no bias) and waste few rays (efficiency).
#include <gtest/gtest.h>

#include <random>

#include "trace/ExactTrace.h"
#include "firstorder/ExitPupilBounds.h"
#include "firstorder/Focus.h"
#include "firstorder/Pupils.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

struct BoundsCase {
    LensSystem lens;
    double filmZ;
    ExitPupilBounds bounds;
};

// dgauss.50mm with its stop opened to 10 mm, focused at 3 m, 35 mm film diagonal (the
// ARCHITECTURE.md benchmark setting where pbrt-v3 wastes 24% of its camera rays).
BoundsCase dgauss50At10mm() {
    const LensSystem table = loadLensSystem(test::lensPath("dgauss.50mm.dat"));
    const LensSystem lens = withStopDiameter(table, 10.0);
    const FirstOrder fo = computeFirstOrder(lens);
    const FocusResult focus = focusAt(lens, fo, computePupils(lens), 3000.0);
    return {lens, focus.imageZExact, computeExitPupilBounds(lens, focus.imageZExact, 17.5)};
}

TEST(ExitPupilBounds, FewRaysBlockedOnDgauss50At10mmStop) {
    const BoundsCase c = dgauss50At10mm();
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int blocked = 0, total = 0;
    for (int i = 0; i < 200000; ++i) {
        // Film points uniform over the 35 mm-diagonal 1:1 film (the benchmark's 400x400 frame).
        const double half = 17.5 / std::sqrt(2.0);
        const double fx = (2 * u(rng) - 1) * half, fy = (2 * u(rng) - 1) * half;
        const PupilSample s = sampleExitPupil(c.bounds, fx, fy, u(rng), u(rng));
        ++total;
        if (!(s.area > 0)) {
            ++blocked;
            continue;
        }
        const Vec3 from{fx, fy, c.filmZ};
        if (!traceRay(c.lens, {from, normalize(s.point - from)}, TraceDirection::FilmToScene).ok()) ++blocked;
    }
    const double fraction = double(blocked) / total;
    RecordProperty("blocked_fraction", std::to_string(fraction));
    EXPECT_LT(fraction, 0.05) << "blocked " << fraction;
}

TEST(ExitPupilBounds, ContainEveryPassingRay) {
    const BoundsCase c = dgauss50At10mm();
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double extent = 1.5 * c.lens.surfaces.back().apertureRadius;
    int passing = 0, outside = 0;
    for (int i = 0; i < 300000; ++i) {
        const double r = 17.5 * std::sqrt(u(rng)), phi = 2 * M_PI * u(rng);
        const double fx = r * std::cos(phi), fy = r * std::sin(phi);
        const double x = (2 * u(rng) - 1) * extent, y = (2 * u(rng) - 1) * extent;
        const Vec3 from{fx, fy, c.filmZ};
        if (!traceRay(c.lens, {from, normalize(Vec3{x, y, c.bounds.aimZ} - from)}, TraceDirection::FilmToScene).ok())
            continue;
        ++passing;
        if (!insideExitPupilBounds(c.bounds, fx, fy, x, y)) ++outside;
    }
    ASSERT_GT(passing, 1000);
    EXPECT_LT(double(outside) / passing, 1e-3) << outside << " of " << passing << " passing rays outside the bounds";
}

TEST(ExitPupilBounds, SamplesLieInsideAndAreaMatchesTheCentralDisc) {
    const BoundsCase c = dgauss50At10mm();
    // On the axis the region is the exit pupil seen through the rear element: nearly a disc.
    const PupilSample s = sampleExitPupil(c.bounds, 0, 0, 0.3, 0.7);
    EXPECT_TRUE(insideExitPupilBounds(c.bounds, 0, 0, s.point.x, s.point.y));
    EXPECT_GT(s.area, 0);
    for (double u1 : {0.01, 0.5, 0.99})
        for (double u2 : {0.0, 0.5, 0.999}) {
            const PupilSample t = sampleExitPupil(c.bounds, 10.0, -4.0, u1, u2);
            EXPECT_TRUE(insideExitPupilBounds(c.bounds, 10.0, -4.0, t.point.x, t.point.y));
        }
}

}  // namespace
}  // namespace lenslab
