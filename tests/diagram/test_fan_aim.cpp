// A ray fan of n rays comes from the object side and is aimed evenly across kFanOverfill times the
// aperture stop, both ends included: ray k crosses the stop's plane at (-1 + 2k / (n - 1)) 1.2 r_stop.
// Rays inside the stop reach the film; the two outside it stop at the stop.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "RayFans.h"

using namespace lenslab;

namespace {

LensAnalysis dgaussAt(std::optional<double> fstop, double focus) {
    return analyzeLens(loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"), fstop, focus);
}

}  // namespace

TEST(FanAim, RaysComeFromTheObjectSideAndSpanTheOverfilledStop) {
    const LensAnalysis a = dgaussAt(8.0, std::numeric_limits<double>::infinity());
    FanSetup setup;
    setup.filmZ = a.focus.imageZExact;
    setup.rays = 5;
    setup.startZ = 100;
    const std::vector<FanRay> fan = traceRayFans(a, RayModel::Exact, setup);
    ASSERT_EQ(fan.size(), 5u);
    const Surface& stop = a.lens.stop();
    for (int k = 0; k < 5; ++k) {
        const double expected = (-1 + 2.0 * k / 4) * kFanOverfill * stop.apertureRadius;
        const std::vector<ZY>& p = fan[k].points;
        // A distant object: every ray starts on the start plane, parallel to the axis.
        EXPECT_DOUBLE_EQ(p.front().z, 100.0) << "ray " << k;
        EXPECT_NEAR(p[1].y, p[0].y, 1e-9) << "ray " << k;
        const bool outside = std::abs(expected) > stop.apertureRadius;
        EXPECT_EQ(fan[k].blocked, outside) << "ray " << k;
        // The stop is a flat diaphragm: the point where the ray crosses it is at its z.
        const ZY atStop = outside ? p.back() : p.at(a.lens.stopIndex + 1);
        EXPECT_NEAR(atStop.z, stop.z, 1e-9) << "ray " << k;
        EXPECT_NEAR(atStop.y, expected, 1e-6) << "ray " << k;
        if (!outside) {
            EXPECT_NEAR(p.back().z, setup.filmZ, 1e-9) << "ray " << k;
        }
    }
}

TEST(FanAim, ANearObjectsRaysStartAtTheObjectPoint) {
    const double focus = 600;
    const LensAnalysis a = dgaussAt(4.0, focus);
    FanSetup setup;
    setup.filmZ = a.focus.imageZExact;
    setup.rays = 7;
    setup.fieldDegrees = 5;
    setup.startZ = 2 * focus;  // the object is nearer than the start plane: rays leave the object itself
    const std::vector<FanRay> fan = traceRayFans(a, RayModel::Exact, setup);
    ASSERT_EQ(fan.size(), 14u);
    // The field's object point: at the plane of focus, where a 5 degree chief ray toward the entrance
    // pupil's centre comes from (toward +y, so it images below the axis).
    const double objectZ = a.lens.frontZ() + focus;
    const double fieldY = (objectZ - a.pupils.entrance.z) * std::tan(5 * 3.14159265358979323846 / 180);
    for (const FanRay& ray : fan) {
        EXPECT_NEAR(ray.points.front().z, objectZ, 1e-9);
        EXPECT_NEAR(ray.points.front().y, ray.offAxis ? fieldY : 0.0, 1e-9);
    }
}
