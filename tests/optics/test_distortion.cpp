// Distortion by exact chief-ray tracing: the stop-position rule of a single lens, a fisheye's
// barrel, and third-order growth near the axis.
#include <gtest/gtest.h>

#include <cmath>

#include "firstorder/ChiefRay.h"
#include "analysis/Distortion.h"
#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "trace/NearAxis.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

Surface sphere(double z, double radius, double indexAfter, double apertureRadius) {
    Surface s;
    s.z = z;
    s.radius = radius;
    s.curvature = radius == 0 ? 0 : 1 / radius;
    s.indexAfter = indexAfter;
    s.apertureRadius = apertureRadius;
    return s;
}

// An equiconvex singlet (f about 50 mm), its stop at `stopGap` in front of the first vertex (0: at
// the middle of the glass).
LensSystem stoppedSinglet(double stopGap) {
    Surface stop = sphere(0, 0, 1, 2);
    stop.isStop = true;
    LensSystem lens;
    if (stopGap == 0) {
        stop.z = -1;
        stop.indexAfter = 1.5;
        lens.surfaces = {sphere(0, 50, 1.5, 10), stop, sphere(-2, -50, 1, 10)};
        lens.stopIndex = 1;
    } else {
        lens.surfaces = {stop, sphere(-stopGap, 50, 1.5, 10), sphere(-stopGap - 2, -50, 1, 10)};
        lens.stopIndex = 0;
    }
    return lens;
}

double distortionAt(const LensSystem& lens, double degrees) {
    const auto curve = distortionCurve(lens, computeFirstOrder(lens), degrees, 2);
    EXPECT_TRUE(curve.back().found);
    return curve.back().distortionPercent;
}


}  // namespace

TEST(Distortion, ChiefRayCrossesTheStopOnTheAxis) {
    const LensSystem lens = bundled("dgauss.50mm.dat");
    for (double field : {1.0, 10.0, 20.0}) {
        const auto in = chiefRay(lens, field);
        ASSERT_TRUE(in) << field;
        TraceOptions options;
        options.end = lens.stopIndex;
        options.ignoreApertures = true;
        const TraceResult r = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
        ASSERT_TRUE(r.ok());
        EXPECT_NEAR(heightAtZ(r.ray, lens.stop().z), 0.0, 1e-9) << field;
        EXPECT_NEAR(std::acos(-in->direction.z) * 180 / M_PI, field, 1e-12);
    }
}

TEST(Distortion, SingleLensStopInFrontIsBarrelStopAtTheLensIsNearlyFree) {
    const double inFront = distortionAt(stoppedSinglet(20), 15);
    const double atLens = distortionAt(stoppedSinglet(0), 15);
    EXPECT_LT(inFront, -0.3);
    EXPECT_LT(std::fabs(atLens), 0.1 * std::fabs(inFront));
}

TEST(Distortion, FisheyeIsStronglyBarrelAtLargeField) {
    const LensSystem lens = bundled("fisheye.10mm.dat");
    const auto curve = distortionCurve(lens, computeFirstOrder(lens), 75, 16);
    for (std::size_t k = 1; k < curve.size(); ++k) {
        ASSERT_TRUE(curve[k].found) << curve[k].fieldDegrees;
        EXPECT_LT(curve[k].distortionPercent, curve[k - 1].distortionPercent) << curve[k].fieldDegrees;
    }
    EXPECT_LT(curve.back().distortionPercent, -50.0);
}

TEST(Distortion, GrowsWithTheSquareOfTheFieldNearTheAxis) {
    const LensSystem lens = bundled("dgauss.50mm.dat");
    const double d1 = distortionAt(lens, 1.0), d2 = distortionAt(lens, 2.0);
    EXPECT_NEAR(d2 / d1, 4.0, 0.2);
    EXPECT_LT(std::fabs(distortionAt(lens, 20.0)), 5.0);  // a well-corrected double Gauss
}
