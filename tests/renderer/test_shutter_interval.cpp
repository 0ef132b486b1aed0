// The realistic camera's exposure is the shutter interval's length, close - open, as pbrt-v3's
// RealisticCamera weights it: an interval that does not start at 0 tells that from `close` alone.
#include <gtest/gtest.h>

#include "TestScenes.h"

namespace lenslab {
namespace {

// The film seeing a uniform sky through dgauss.50mm, with the given shutter parameters.
double meanWithShutter(const test::TempDir& dir, const std::string& name, const std::string& shutter) {
    const std::string scene = dir.write(name, test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 8 " + shutter) +
                                                  "\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\nWorldEnd\n");
    return test::meanLum(test::render(scene, 8, 8, 4).image);
}

TEST(ShutterInterval, ExposureIsCloseMinusOpen) {
    test::TempDir dir;
    const double unit = meanWithShutter(dir, "unit.pbrt", "");  // pbrt's default: open 0, close 1
    ASSERT_GT(unit, 1e-3);
    EXPECT_NEAR(meanWithShutter(dir, "late.pbrt", "\"float shutteropen\" 0.5 \"float shutterclose\" 1") / unit, 0.5, 1e-6);
    EXPECT_NEAR(meanWithShutter(dir, "mid.pbrt", "\"float shutteropen\" 0.25 \"float shutterclose\" 0.5") / unit, 0.25,
                1e-6);
}

}  // namespace
}  // namespace lenslab
