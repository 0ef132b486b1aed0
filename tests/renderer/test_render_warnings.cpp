// A render says what its picture does not show (issue 38): a frame whose camera rays the lens all
// blocks is black, one whose lens draws a small image circle is black beyond it. Each is said in
// the render's result and in the EXR header; an ordinary render says nothing.
#include <gtest/gtest.h>

#include <ImfHeader.h>
#include <ImfStringAttribute.h>
#include <ImfTiledInputFile.h>

#include <cmath>
#include <cstdio>

#include "TestScenes.h"

namespace lenslab {
namespace {

// A stop, a singlet (EFL 80.4 mm) and, 60 mm behind it, a 4 mm baffle: it passes rays only from
// the film's middle, an image circle 7.48 mm across on a 35 mm film (gap-before layout).
constexpr const char* kBaffledSinglet = "0 0 0 6\n50 2 1.5 20\n-200 4 0 20\n0 60 1 4\n";
constexpr double kFilmDiagonal = 35;

// A uniform white sky through `camera`.
std::string warningSkyScene(const test::TempDir& dir, const std::string& camera) {
    return dir.write("sky.pbrt", camera +
                                     "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\" \"integer maxdepth\" 1\n"
                                     "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\nWorldEnd\n");
}

std::string baffledCamera(const test::TempDir& dir) {
    return "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"" + dir.write("baffled.dat", kBaffledSinglet) +
           "\" \"float fstop\" 16 \"float focaldistance\" 1000 \"float filmdiagonal\" 35";
}

std::string exrRenderWarnings(const RenderOutput& out, const test::TempDir& dir) {
    const std::string path = dir.path() + "/out.exr";
    writeImageFile(out, path);
    Imf::TiledInputFile file(path.c_str());
    const auto* warnings = file.header().findTypedAttribute<Imf::StringAttribute>("lenslab.renderWarnings");
    return warnings ? warnings->value() : "(none)";
}

const char* const kSmallCircle =
    "the lens's image circle (7.48 mm across on the film) is smaller than the film (35.00 mm diagonal): beyond it the frame is black";

}  // namespace

TEST(RenderWarnings, ABlackFrameSaysTheLensBlocksEveryCameraRay) {
    test::TempDir dir;
    RenderSettings s;
    s.crop = {0, 0.25, 0, 0.25};  // the frame's corner, all of it outside the image circle
    const RenderOutput out = test::render(warningSkyScene(dir, baffledCamera(dir)), 64, 48, 4, s);
    EXPECT_EQ(test::meanLum(out.image), 0.0);
    EXPECT_EQ(out.stats.cameraRays, 16u * 12u * 4u);
    EXPECT_EQ(out.stats.blockedCameraRays, out.stats.cameraRays);
    const std::string black = "the lens blocks every camera ray (768): the image is black";
    EXPECT_EQ(out.warnings, (std::vector<std::string>{black, kSmallCircle}));
    EXPECT_EQ(exrRenderWarnings(out, dir), black + "\n" + kSmallCircle);
}

TEST(RenderWarnings, AnImageCircleSmallerThanTheFilmIsSaidAndIsWhereTheLightEnds) {
    test::TempDir dir;
    const int width = 64, height = 48;
    const RenderOutput out = test::render(warningSkyScene(dir, baffledCamera(dir)), width, height, 4);
    ASSERT_EQ(out.warnings.size(), 2u);
    EXPECT_EQ(out.warnings[1], kSmallCircle);
    EXPECT_EQ(out.metadata.at("imageCircleDiameterMm"), "7.47758");
    // The lit pixels lie inside the circle, out to within a pixel of its edge.
    const double pixelMm = kFilmDiagonal / std::hypot(width, height), radiusMm = 0.5 * 7.47758;
    double farthest = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (test::lum(out.image, x, y) > 0)
                farthest = std::max(farthest, pixelMm * std::hypot(x + 0.5 - 0.5 * width, y + 0.5 - 0.5 * height));
    EXPECT_LT(farthest, radiusMm + pixelMm);
    EXPECT_GT(farthest, radiusMm - 1.5 * pixelMm);
    // Outside the circle every ray is blocked: at least that share of the frame's.
    const double filmArea = width * height * pixelMm * pixelMm, outside = 1 - M_PI * radiusMm * radiusMm / filmArea;
    const double blocked = double(out.stats.blockedCameraRays) / double(out.stats.cameraRays);
    EXPECT_GT(blocked, outside);
    char dark[96];
    std::snprintf(dark, sizeof dark, "the lens blocks %.1f%% of the camera rays: most of the frame is dark", 100 * blocked);
    EXPECT_EQ(out.warnings[0], dark);
    EXPECT_EQ(exrRenderWarnings(out, dir), out.warnings[0] + "\n" + kSmallCircle);
}

TEST(RenderWarnings, AnOrdinaryLensRenderSaysNothing) {
    test::TempDir dir;
    const RenderOutput out = test::render(
        warningSkyScene(dir, test::courseCamera("dgauss.dat", "\"float fstop\" 4 \"float focaldistance\" 1000 \"float filmdiagonal\" 35")), 32, 24, 2);
    EXPECT_LT(out.stats.blockedCameraRays, out.stats.cameraRays / 2);
    EXPECT_TRUE(out.warnings.empty()) << out.warnings.front();
    EXPECT_EQ(exrRenderWarnings(out, dir), "(none)");
}

}  // namespace lenslab
