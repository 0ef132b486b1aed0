// A spot light without "coneangle" and "conedeltaangle" takes pbrt-v3's 30 and 5 degrees: full
// intensity inside 25 degrees of its axis, pbrt-v3's quartic falloff to 30, nothing beyond.
#include <gtest/gtest.h>

#include <cmath>

#include "RadianceProbe.h"

namespace lenslab {
namespace {

// The radiance the default spot (at the origin, aimed down +z, intensity 1) sends to the point
// one unit away at `degrees` off its axis (none where it declines the sample).
double radianceAt(const Light& spot, double degrees) {
    const double a = degrees * M_PI / 180;
    LightSample s;
    return spot.sample({float(std::sin(a)), 0, float(std::cos(a))}, 0.5f, 0.5f, s) ? s.radiance.y : 0.0;
}

TEST(SpotLightDefaults, ConeOf30DegreesWithA5DegreeFalloff) {
    const auto spot = test::lightFrom("spot", {});
    const double cos25 = std::cos(25 * M_PI / 180), cos30 = std::cos(30 * M_PI / 180);
    EXPECT_NEAR(radianceAt(*spot, 20), 1, 1e-5);
    EXPECT_NEAR(radianceAt(*spot, 27.5), std::pow((std::cos(27.5 * M_PI / 180) - cos30) / (cos25 - cos30), 4), 1e-4);
    EXPECT_EQ(radianceAt(*spot, 32), 0);
}

}  // namespace
}  // namespace lenslab
