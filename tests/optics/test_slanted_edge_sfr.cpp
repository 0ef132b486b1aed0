// The e-SFR against pictures whose MTF is known in closed form: a straight edge blurred along its
// normal by a Gaussian of sigma pixels, each pixel the mean over its square (sampled 16 x 16 here).
// The picture's MTF along the normal n = (cos a, sin a) is exp(-2 pi^2 sigma^2 f^2) times the
// square pixel's sinc(f cos a) sinc(f sin a); the method adds its quarter-pixel bins' sinc(f / 4).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/SlantedEdgeSfr.h"
#include "prescription/Pi.h"

namespace lenslab {
namespace {

double sinc(double x) { return x == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }

// An edge through (cx, cy) (pixels from the top-left corner) whose normal, dark to bright, makes
// `normalDegrees` with +x (y down); contrast from `dark` to `bright`.
PixelRegion blurredEdge(int width, int height, double cx, double cy, double normalDegrees, double sigma,
                        double dark = 0.1, double bright = 0.9) {
    const double nx = std::cos(normalDegrees * kPi / 180), ny = std::sin(normalDegrees * kPi / 180);
    PixelRegion r{width, height, {}};
    constexpr int kSub = 16;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0;
            for (int j = 0; j < kSub; ++j)
                for (int i = 0; i < kSub; ++i) {
                    const double d = (x + (i + 0.5) / kSub - cx) * nx + (y + (j + 0.5) / kSub - cy) * ny;
                    sum += sigma > 0 ? 0.5 * std::erfc(-d / (sigma * std::sqrt(2.0))) : (d > 0 ? 1.0 : d < 0 ? 0.0 : 0.5);
                }
            r.values.push_back(dark + (bright - dark) * sum / (kSub * kSub));
        }
    return r;
}

std::vector<double> frequencies(double highest, int count) {
    std::vector<double> f;
    for (int k = 0; k < count; ++k) f.push_back(highest * k / (count - 1));
    return f;
}

double expectedSfr(double f, double normalDegrees, double sigma) {
    const double a = normalDegrees * kPi / 180;
    return std::exp(-2 * kPi * kPi * sigma * sigma * f * f) * sinc(f * std::cos(a)) * sinc(f * std::sin(a)) * sinc(f / 4);
}

void expectSfrNear(const EdgeSfr& e, double normalDegrees, double sigma, double tolerance) {
    for (std::size_t k = 0; k < e.frequencies.size(); ++k)
        EXPECT_NEAR(e.sfr[k], expectedSfr(e.frequencies[k], normalDegrees, sigma), tolerance)
            << "at " << e.frequencies[k] << " cycles/pixel";
}

TEST(SlantedEdgeSfr, GaussianBlurAndPixelUpToNyquist) {
    for (double sigma : {0.0, 0.7, 1.5}) {
        SCOPED_TRACE("sigma " + std::to_string(sigma));
        // A near-vertical edge, 5 degrees from the column: its normal 5 degrees from +x.
        const EdgeSfr e = slantedEdgeSfr(blurredEdge(96, 60, 48.3, 30, 5, sigma), frequencies(0.5, 11));
        EXPECT_TRUE(e.alongRows);
        EXPECT_NEAR(std::abs(e.angleDegrees), 5, 0.05);
        EXPECT_NEAR(e.normalX, std::cos(5 * kPi / 180), 1e-3);
        EXPECT_NEAR(e.normalY, std::sin(5 * kPi / 180), 1e-3);
        EXPECT_NEAR(e.centreX, 48.3, 0.05);
        EXPECT_NEAR(e.sfr.front(), 1.0, 1e-12);
        // Unblurred, the pixel's own edge spread has content past the bins' Nyquist (2 cycles per
        // pixel: sinc(3.5) is -0.09) that folds back: 1% at Nyquist.
        expectSfrNear(e, 5, sigma, sigma == 0 ? 0.01 : 0.006);
    }
}

TEST(SlantedEdgeSfr, NearHorizontalEdgeBrightAboveIsMeasuredAcrossColumns) {
    // Normal pointing up (-y) and 6 degrees toward -x: bright above the edge.
    const double normal = -96;
    const EdgeSfr e = slantedEdgeSfr(blurredEdge(60, 64, 30, 31.6, normal, 1.0, 0.05, 0.8), frequencies(0.5, 11));
    EXPECT_FALSE(e.alongRows);
    EXPECT_NEAR(std::abs(e.angleDegrees), 6, 0.05);
    EXPECT_NEAR(e.normalX, std::cos(normal * kPi / 180), 1e-3);
    EXPECT_NEAR(e.normalY, std::sin(normal * kPi / 180), 1e-3);
    EXPECT_NEAR(e.centreX, 30, 1e-9);
    EXPECT_NEAR(e.centreY, 31.6, 0.05);
    expectSfrNear(e, normal, 1.0, 0.006);
}

TEST(SlantedEdgeSfr, DarkToBrightEitherWayGivesTheSameSfr) {
    const EdgeSfr up = slantedEdgeSfr(blurredEdge(48, 60, 24, 30, 4, 1.2, 0.1, 0.9), frequencies(0.5, 6));
    const EdgeSfr down = slantedEdgeSfr(blurredEdge(48, 60, 24, 30, 4, 1.2, 0.9, 0.1), frequencies(0.5, 6));
    EXPECT_NEAR(down.normalX, -up.normalX, 1e-9);
    for (std::size_t k = 0; k < up.sfr.size(); ++k) EXPECT_NEAR(up.sfr[k], down.sfr[k], 1e-9);
}

TEST(SlantedEdgeSfr, ANarrowerBlurMeasuresHigher) {
    // Would fail if the transform ignored the positions (a constant) or the blur.
    const std::vector<double> f{0.25};
    const double sharp = slantedEdgeSfr(blurredEdge(48, 60, 24, 30, 5, 0.5), f).sfr[0];
    const double soft = slantedEdgeSfr(blurredEdge(48, 60, 24, 30, 5, 2.0), f).sfr[0];
    EXPECT_GT(sharp, soft + 0.3);
}

void expectRefused(const PixelRegion& r, const std::string& part) {
    try {
        slantedEdgeSfr(r, {0, 0.25});
        FAIL() << "no error; expected one about " << part;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST(SlantedEdgeSfr, RefusesRegionsWithoutAUsableEdge) {
    expectRefused(PixelRegion{40, 40, std::vector<double>(1600, 0.5)}, "no step");
    expectRefused(blurredEdge(40, 40, 20, 20, 0, 1.0), "slanted 0");
    expectRefused(blurredEdge(40, 40, 20, 20, 40, 1.0), "1 to 30");
    expectRefused(blurredEdge(40, 6, 20, 3, 5, 1.0), "at least 8 x 8");
    expectRefused(blurredEdge(40, 8, 20, 4, 3, 1.0), "whole turn");
    PixelRegion nan = blurredEdge(40, 40, 20, 20, 5, 1.0);
    nan.values[17] = std::nan("");
    expectRefused(nan, "not finite");
    EXPECT_THROW(slantedEdgeSfr(blurredEdge(40, 40, 20, 20, 5, 1.0), {1.5}), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
