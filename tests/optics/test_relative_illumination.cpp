// Relative illumination by exact tracing: the cos^4 law for a bare stop, and the falloff of a real lens.
#include <gtest/gtest.h>

#include <cmath>

#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "prescription/OpticsError.h"
#include "analysis/RelativeIllumination.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

// A lone circular stop at z = 0: nothing vignettes, so only the cos^4 law remains.
LensSystem bareStop(double radius) {
    LensSystem lens;
    Surface s;
    s.apertureRadius = radius;
    s.isStop = true;
    lens.surfaces = {s};
    lens.stopIndex = 0;
    return lens;
}


}  // namespace

TEST(RelativeIllumination, BareStopFollowsCosineFourthLaw) {
    const double filmDistance = 50;
    const auto samples = relativeIllumination(bareStop(0.5), -filmDistance, 40.0);
    ASSERT_EQ(samples.size(), 48u);
    for (const auto& s : samples) {
        SCOPED_TRACE(s.filmRadius);
        const double c = std::cos(std::atan(s.filmRadius / filmDistance));
        EXPECT_NEAR(s.relativeIllumination, c * c * c * c, 2e-3);
        EXPECT_NEAR(s.passingArea, 1.0, 1e-9);  // the stop is the aiming plane: no vignetting
    }
}

// A cover glass 0.2 mm before the film (as many real prescriptions end) leaves the rear vertex's
// plane so close to the film that the light from a film point crosses it in a spot far smaller than
// a search cell: the aim moves to the front vertex's plane, and the stop's cos^4 law comes out as
// without the plate (a 0.3 mm plate 50 mm behind the stop moves the rays by well under 1%).
TEST(RelativeIllumination, ACoverGlassJustBeforeTheFilmStillGivesTheFalloff) {
    const double filmDistance = 50;
    LensSystem lens = bareStop(0.5);
    Surface front, back;
    front.z = -49.5;
    front.apertureRadius = back.apertureRadius = 60;
    front.indexAfter = 1.5;
    back.z = -49.8;
    lens.surfaces.push_back(front);
    lens.surfaces.push_back(back);
    const auto plate = relativeIllumination(lens, -filmDistance, 40.0);
    const auto bare = relativeIllumination(bareStop(0.5), -filmDistance, 40.0);
    ASSERT_EQ(plate.size(), bare.size());
    for (std::size_t k = 0; k < plate.size(); ++k) {
        SCOPED_TRACE(plate[k].filmRadius);
        EXPECT_NEAR(plate[k].relativeIllumination, bare[k].relativeIllumination, 0.01);
    }
    EXPECT_LT(plate.back().relativeIllumination, 0.5);  // the corner of a 40 mm field: cos^4(38.7 deg) = 0.37
}

TEST(RelativeIllumination, DoubleGaussFallsOffMonotonicallyFromOneAtTheCentre) {
    const LensSystem lens = bundled("dgauss.50mm.dat");
    const FirstOrder fo = computeFirstOrder(lens);
    const auto samples = relativeIllumination(lens, fo.zFPrime, 21.6);  // 35 mm film half-diagonal
    EXPECT_DOUBLE_EQ(samples.front().relativeIllumination, 1.0);
    EXPECT_DOUBLE_EQ(samples.front().passingArea, 1.0);
    for (std::size_t k = 1; k < samples.size(); ++k) {
        SCOPED_TRACE(samples[k].filmRadius);
        EXPECT_LE(samples[k].relativeIllumination, samples[k - 1].relativeIllumination + 2e-3);
        // cos^4 only takes light away: illumination never exceeds the unweighted passing area.
        EXPECT_LE(samples[k].relativeIllumination, samples[k].passingArea + 1e-3);
    }
    // Wide open at the corner of 35 mm film a double Gauss keeps well under two thirds of the light.
    EXPECT_LT(samples.back().relativeIllumination, 0.65);
    EXPECT_GT(samples.back().relativeIllumination, 0.05);
}

// A rotationally symmetric lens is measured over the half y >= 0 of each grid, mirrored: the same
// numbers as the whole grid gives, here forced by marking the same lens decentred (no motion, so
// only the symmetry shortcut is lost). An odd grid cannot be halved and is refused.
TEST(RelativeIllumination, HalfGridOfASymmetricLensEqualsTheWholeGrid) {
    const LensSystem lens = bundled("dgauss.50mm.dat");
    LensSystem whole = lens;
    whole.decentred = true;
    ASSERT_TRUE(lens.isRotationallySymmetric());
    ASSERT_FALSE(whole.isRotationallySymmetric());
    const FirstOrder fo = computeFirstOrder(lens);
    const auto half = relativeIllumination(lens, fo.zFPrime, 30.0, {13, 64});
    const auto full = relativeIllumination(whole, fo.zFPrime, 30.0, {13, 64});
    ASSERT_EQ(half.size(), full.size());
    for (std::size_t k = 0; k < half.size(); ++k) {
        SCOPED_TRACE(half[k].filmRadius);
        EXPECT_NEAR(half[k].relativeIllumination, full[k].relativeIllumination, 1e-12);
        EXPECT_NEAR(half[k].passingArea, full[k].passingArea, 1e-12);
    }
    EXPECT_LT(half.back().relativeIllumination, 0.5);  // vignetted at 30 mm: the comparison is not of ones
    EXPECT_THROW(relativeIllumination(lens, fo.zFPrime, 30.0, {13, 63}), OpticsError);
}

TEST(RelativeIllumination, ImageCircleEndsWhereNoLightPasses) {
    const LensSystem lens = bundled("dgauss.50mm.dat");
    const FirstOrder fo = computeFirstOrder(lens);
    const double circle = imageCircleRadius(lens, fo.zFPrime, 200.0);
    EXPECT_GT(circle, 21.6);
    EXPECT_LT(circle, 100.0);
    const auto beyond = relativeIllumination(lens, fo.zFPrime, 1.05 * circle, {11, 64});
    EXPECT_GT(beyond[9].relativeIllumination, 0.0);  // at 0.945 of the circle
    EXPECT_EQ(beyond.back().relativeIllumination, 0.0);
    EXPECT_DOUBLE_EQ(imageCircleRadius(bareStop(1.0), -50.0, 30.0), 30.0);
}

TEST(RelativeIllumination, RefusesAFilmInFrontOfTheLens) {
    EXPECT_THROW(relativeIllumination(bareStop(1.0), 10.0, 5.0), OpticsError);
}
