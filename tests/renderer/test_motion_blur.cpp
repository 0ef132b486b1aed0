// Motion blur against closed forms: a sphere moving along a pixel row leaves a streak as long as its
// path in the image, each pixel as bright as the time the sphere covers it; the shutter interval
// moves the exposure in time without changing it; ActiveTransform and CoordSysTransform keep pbrt's
// scoping; a moving camera sees what a moving world shows it; rays at one moment see the transform
// of that moment; a scene without motion renders as before.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "TestScenes.h"
#include "core/Transform.h"

namespace lenslab {
namespace {

// An orthographic camera looking down +z at a 128 x 16 image of 1/16-unit pixels ([-4, 4] x
// [-0.5, 0.5]), box filter; a white matte world lit head-on by a distant light of irradiance pi, so
// that a surface facing the camera at angle theta has radiance cos theta. No other light: black
// behind.
constexpr int kWidth = 128, kHeight = 16;
constexpr double kPixelsPerUnit = 16, kRadius = 0.25;

std::string orthographicScene(const std::string& camera, const std::string& shutter, const std::string& world) {
    return camera + "Camera \"orthographic\" \"float screenwindow\" [-4 4 -0.5 0.5] " + shutter +
           "\nFilm \"image\" \"integer xresolution\" 128 \"integer yresolution\" 16\n"
           "PixelFilter \"box\"\nIntegrator \"directlighting\" \"integer maxdepth\" 1\n"
           "WorldBegin\nLightSource \"distant\" \"point from\" [0 0 -5] \"point to\" [0 0 0] \"rgb L\" [3.14159265 3.14159265 3.14159265]\n"
           "Material \"matte\" \"rgb Kd\" [1 1 1]\n" + world + "\nWorldEnd\n";
}

const std::string kStillCamera = "LookAt 0 0 -5  0 0 0  0 1 0\n";
// Between the transform times 0 and 1 the sphere's centre runs from x = -1 to x = 1 (32 pixels).
const std::string kMovingSphere =
    "AttributeBegin\n ActiveTransform StartTime\n Translate -1 0 0\n ActiveTransform EndTime\n Translate 1 0 0\n"
    " ActiveTransform All\n Shape \"sphere\" \"float radius\" 0.25\nAttributeEnd\n";

// The closed form of one pixel: cos theta of the sphere at centre x = c(t) = -1 + 2t, averaged over
// the pixel's square and the shutter interval [open, close] (a fine midpoint rule).
double expectedPixel(int px, int py, double open, double close) {
    constexpr int kSub = 16, kTimes = 128;
    double sum = 0;
    for (int k = 0; k < kTimes; ++k) {
        const double t = open + (close - open) * (k + 0.5) / kTimes, c = -1 + 2 * std::clamp(t, 0.0, 1.0);
        for (int i = 0; i < kSub; ++i)
            for (int j = 0; j < kSub; ++j) {
                const double x = -4 + (px + (i + 0.5) / kSub) / kPixelsPerUnit;
                const double y = 0.5 - (py + (j + 0.5) / kSub) / kPixelsPerUnit;
                const double rho2 = ((x - c) * (x - c) + y * y) / (kRadius * kRadius);
                if (rho2 < 1) sum += std::sqrt(1 - rho2);
            }
    }
    return sum / (kTimes * kSub * kSub);
}

// Pixels of row py holding any light.
int litPixels(const Image& im, int py) {
    int n = 0;
    for (int x = 0; x < im.width; ++x) n += test::lum(im, x, py) > 0;
    return n;
}

double imageSum(const Image& im) { return test::meanLum(im) * im.width * im.height; }

void expectStreak(const Image& im, double open, double close, int expectedLength) {
    // The row just above the path: the streak spans the path in the image plus the sphere's
    // diameter, in pixels.
    EXPECT_EQ(litPixels(im, 7), expectedLength);
    double worst = 0, peak = 0, squares = 0;
    int lit = 0;
    for (int py : {5, 7, 8}) {
        for (int px = 0; px < kWidth; ++px) {
            const double want = expectedPixel(px, py, open, close), error = test::lum(im, px, py) - want;
            peak = std::max(peak, want);
            worst = std::max(worst, std::fabs(error));
            squares += error * error;
            lit += want > 0;
        }
    }
    // Each pixel to 2% of the brightest in the mean (256 samples over area and time), 5% at worst.
    EXPECT_LT(std::sqrt(squares / lit), 0.02 * peak) << "peak " << peak;
    EXPECT_LT(worst, 0.05 * peak) << "peak " << peak;
    // Every pixel sees the whole sphere's light for the time it covers it: the image holds the
    // still sphere's total, the integral of cos theta over its disc, (2/3) pi r^2 in pixels.
    EXPECT_NEAR(imageSum(im), 2.0 / 3 * M_PI * std::pow(kRadius * kPixelsPerUnit, 2), 0.01 * 33.5);
}

TEST(MotionBlur, AMovingSphereLeavesAStreakOfItsPathsLengthAndTheRightBrightness) {
    test::TempDir dir;
    const Image im = test::render(dir.write("s.pbrt", orthographicScene(kStillCamera, "", kMovingSphere)),
                                  kWidth, kHeight, 256).image;
    expectStreak(im, 0, 1, 32 + 8);
}

TEST(MotionBlur, TheShutterIntervalMovesTheExposureWithoutChangingIt) {
    // Open from 0.5 to 1: the sphere runs from x = 0 to 1, half the streak at the same total light.
    test::TempDir dir;
    const Image im = test::render(dir.write("s.pbrt", orthographicScene(kStillCamera,
                                  "\"float shutteropen\" 0.5 \"float shutterclose\" 1", kMovingSphere)),
                                  kWidth, kHeight, 256).image;
    expectStreak(im, 0.5, 1, 16 + 8);
}

TEST(MotionBlur, ActiveTransformEndsWithItsBlockAndAtWorldBegin) {
    // As in pbrt-v3 and pbrt-v4, ActiveTransform is part of the graphics state: AttributeEnd and
    // TransformEnd restore it and WorldBegin resets it to both keyframes. The Translate after each
    // scope thus moves both keyframes, and the sphere stands still at x = -1 (its disc, 8 pixels
    // wide); an EndTime left active would move it from x = 0 to -1 instead (24 pixels).
    const std::string still = "Translate -1 0 0\nShape \"sphere\" \"float radius\" 0.25\n";
    const std::pair<std::string, std::string> cases[] = {
        {kStillCamera, "AttributeBegin\n ActiveTransform EndTime\nAttributeEnd\n" + still},
        {kStillCamera, "TransformBegin\n ActiveTransform EndTime\nTransformEnd\n" + still},
        {kStillCamera + "ActiveTransform EndTime\n", still},
    };
    test::TempDir dir;
    for (const auto& [camera, world] : cases) {
        SCOPED_TRACE(camera + world);
        expectStreak(test::render(dir.write("s.pbrt", orthographicScene(camera, "", world)), kWidth, kHeight, 64).image,
                     0, 0, 8);
    }
}

TEST(MotionBlur, CoordSysTransformRestoresBothKeyframes) {
    // A named system saved from a moving transform brings back its whole motion even while only
    // StartTime is active (pbrt-v3 and pbrt-v4 set both keyframes): the sphere runs from x = -1 to 1.
    test::TempDir dir;
    const std::string world =
        "ActiveTransform StartTime\nTranslate -1 0 0\nActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\n"
        "CoordinateSystem \"path\"\nIdentity\nActiveTransform StartTime\nCoordSysTransform \"path\"\n"
        "ActiveTransform All\nShape \"sphere\" \"float radius\" 0.25\n";
    const Image im = test::render(dir.write("s.pbrt", orthographicScene(kStillCamera, "", world)), kWidth, kHeight, 256).image;
    expectStreak(im, 0, 1, 32 + 8);
}

TEST(MotionBlur, AMovingCameraSeesWhatAMovingWorldShowsIt) {
    test::TempDir dir;
    const Image world = test::render(dir.write("w.pbrt", orthographicScene(kStillCamera, "", kMovingSphere)),
                                     kWidth, kHeight, 64).image;
    const std::string movingCamera = "ActiveTransform StartTime\nLookAt 1 0 -5  1 0 0  0 1 0\n"
                                     "ActiveTransform EndTime\nLookAt -1 0 -5  -1 0 0  0 1 0\nActiveTransform All\n";
    const Image camera = test::render(dir.write("c.pbrt", orthographicScene(movingCamera, "",
                                      "Shape \"sphere\" \"float radius\" 0.25")), kWidth, kHeight, 64).image;
    double worst = 0;
    for (std::size_t i = 0; i < world.rgb.size(); ++i) worst = std::max(worst, double(std::fabs(world.rgb[i] - camera.rgb[i])));
    EXPECT_LT(worst, 1e-3);
    EXPECT_GT(litPixels(camera, 7), 32);
}

// pbrt's Transform directive for t: its matrix column by column.
std::string transformDirective(const Transform& t) {
    std::string s = "Transform [";
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) s += " " + std::to_string(t.forward.m[r][c]);
    return s + " ]\n";
}

TEST(MotionBlur, RaysAtOneMomentSeeTheTransformOfThatMoment) {
    // A bar instance moving, with the shutter open only at time 0.5, against the bar standing still
    // where pbrt's motion puts it then: Embree's interpolation of the instance is the one lenslab
    // writes. Turning by 90 degrees: still at 45. Squashed to half its height and turning by 60
    // degrees: still at R(30) times the mean of the keyframes' polar stretches (S and R^T S R).
    test::TempDir dir;
    const std::string bar = "ObjectBegin \"bar\"\n Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]"
                            " \"point P\" [-0.45 -0.06 0  0.45 -0.06 0  0.45 0.06 0  -0.45 0.06 0]\nObjectEnd\n";
    const auto renderBar = [&](const std::string& name, const std::string& place) {
        return test::render(dir.write(name, orthographicScene(kStillCamera, "\"float shutteropen\" 0.5 \"float shutterclose\" 0.5",
                                                              bar + "AttributeBegin\n" + place + " ObjectInstance \"bar\"\nAttributeEnd\n")),
                            kWidth, kHeight, 16).image;
    };
    const Transform S = scale(1, 0.5, 1), R = rotate(60, 0, 0, 1);
    Matrix44 meanStretch = transpose(R.forward) * S.forward * R.forward;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) meanStretch.m[r][c] = (meanStretch.m[r][c] + S.forward.m[r][c]) / 2;
    const std::pair<std::string, std::string> cases[] = {
        {"ActiveTransform EndTime\n Rotate 90 0 0 1\n ActiveTransform All\n", "Rotate 45 0 0 1\n"},
        {"Scale 1 0.5 1\n ActiveTransform EndTime\n Rotate 60 0 0 1\n ActiveTransform All\n",
         transformDirective(rotate(30, 0, 0, 1) * makeTransform(meanStretch))},
    };
    for (const auto& [moving, placed] : cases) {
        SCOPED_TRACE(moving);
        const Image turning = renderBar("t.pbrt", moving);
        const Image still = renderBar("s.pbrt", placed);
        double diff = 0;
        for (std::size_t i = 0; i < still.rgb.size(); ++i) diff += std::fabs(still.rgb[i] - turning.rgb[i]);
        EXPECT_LT(diff / still.rgb.size(), 1e-4);
        EXPECT_GT(imageSum(still), 0.9 * 0.5 * 0.9 * 0.12 * 256);  // the bar is there: 90% of its area (squashed or not)
    }
}

TEST(MotionBlur, TransformTimesWithoutMotionRenderBitIdentically) {
    // The same world with and without the motion directives (equal transforms at both times, a
    // shutter interval): the very same pixels.
    test::TempDir dir;
    const std::string world =
        "LightSource \"infinite\" \"rgb L\" [0.3 0.4 0.5]\n"
        "Shape \"sphere\" \"float radius\" 0.3\n"
        "AttributeBegin\n Translate 0.9 0 0.5\n%MOTION%Shape \"trianglemesh\" \"integer indices\" [0 1 2]"
        " \"point P\" [-0.5 -0.4 0  0.5 -0.4 0  0 0.4 0]\nAttributeEnd\n"
        "ObjectBegin \"ball\"\n Shape \"sphere\" \"float radius\" 0.1\nObjectEnd\n"
        "AttributeBegin\n Translate -1 0 0\n%MOTION%ObjectInstance \"ball\"\nAttributeEnd\n";
    const auto scene = [&](const std::string& name, const std::string& options, const std::string& motion) {
        std::string w = world;
        for (std::size_t at; (at = w.find("%MOTION%")) != std::string::npos;) w.replace(at, 8, motion);
        return dir.write(name, options + "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50 " +
                                   (options.empty() ? "" : "\"float shutteropen\" 0.3 \"float shutterclose\" 0.9") +
                                   "\nIntegrator \"path\"\nWorldBegin\n" + w + "\nWorldEnd\n");
    };
    const Image plain = test::render(scene("a.pbrt", "", ""), 48, 32, 8).image;
    const Image timed = test::render(scene("b.pbrt", "TransformTimes 0.2 0.7\n",
                                           " ActiveTransform EndTime\n Translate 0 0 0\n ActiveTransform All\n"), 48, 32, 8).image;
    ASSERT_EQ(plain.rgb.size(), timed.rgb.size());
    EXPECT_EQ(0, std::memcmp(plain.rgb.data(), timed.rgb.data(), plain.rgb.size() * sizeof(float)));
}

}  // namespace
}  // namespace lenslab
