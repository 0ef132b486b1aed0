// A ray fan of n rays aims evenly across kFanOverfill times the exit pupil, both ends included:
// ray k leaves the film point toward height (-1 + 2k / (n - 1)) 1.2 D/2 in the exit pupil's plane.
#include <gtest/gtest.h>

#include <limits>

#include "RayFans.h"

using namespace lenslab;

TEST(FanAim, RaysSpanTheOverfilledExitPupilEndToEnd) {
    const LensAnalysis a = analyzeLens(loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"),
                                       8.0, std::numeric_limits<double>::infinity());
    FanSetup setup;
    setup.filmZ = a.focus.imageZExact;
    setup.rays = 5;
    setup.endZ = 100;
    const std::vector<FanRay> fan = traceRayFans(a, RayModel::Exact, setup);
    ASSERT_EQ(fan.size(), 5u);
    const double exitZ = a.pupils.exit.z, reach = kFanOverfill * a.pupils.exit.diameter / 2;
    for (int k = 0; k < 5; ++k) {
        const ZY p = fan[k].points.at(0), q = fan[k].points.at(1);  // the film point and the first surface
        const double yAtExit = p.y + (q.y - p.y) * (exitZ - p.z) / (q.z - p.z);
        EXPECT_NEAR(yAtExit, (-1 + 2.0 * k / 4) * reach, 1e-9) << "ray " << k;
    }
}
