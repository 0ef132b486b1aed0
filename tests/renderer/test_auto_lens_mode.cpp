// Mode "auto": the thick lens where its predicted film position and brightness errors stay under the
// thresholds, over at least nine tenths of the film (else nowhere), the exact trace elsewhere, with
// the work limited to the film radii the crop window reaches.
#include <gtest/gtest.h>

#include <cmath>

#include "cameras/RealisticCamera.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// A 36 x 24 mm film at 240 x 160 pixels (0.15 mm pixels), focused at 5.5 m.
RealisticParams params(const std::string& lens, double fstop, LensMode mode) {
    RealisticParams p = realisticParams(test::lensPath(lens), fstop, 5500);
    p.filmDiagonalMm = std::hypot(36.0, 24.0);
    p.mode = mode;
    return p;
}

TEST(AutoLensMode, FisheyeTracesExactlyEverywhereWhenTheThickLensFitsOnlyTheCentre) {
    const RealisticCamera c(params("fisheye.10mm.dat", 5.6, LensMode::Auto), {}, 240, 160, 0.5);
    // The prediction: the worst exact ray strays 0.04 mm at r = 2 mm (under 0.075 mm, half a
    // pixel), 0.25 mm at 4 mm: the fisheye's projection leaves the thick lens's (rectilinear).
    const auto& e = c.thickLensErrors();
    ASSERT_GE(e.size(), 3u);
    EXPECT_LT(e[1].maxErrorMm, 0.075);
    EXPECT_GT(e[2].maxErrorMm, 0.2);
    // The thick lens would be allowed on the disc r < 2 mm: 1.5% of the film, not worth a split.
    EXPECT_EQ(c.describe().at("thickLensShareOfFilm"), "0.0146");
    EXPECT_FALSE(c.lensModes().usesThick());
    EXPECT_EQ(c.describe().at("lensModelByFilmRadius"), "exact for 0 <= r <= 21.9 mm");
}

TEST(AutoLensMode, ATelephotoFivePercentTooBrightIsTracedExactlyThoughItsPositionsFit) {
    const RealisticCamera c(params("telephoto.250mm.dat", 5.6, LensMode::Auto), {}, 240, 160, 0.5);
    const auto& e = c.thickLensErrors();
    ASSERT_EQ(e.size(), 12u);
    for (std::size_t i = 0; i + 1 < e.size(); ++i) {
        // Within half a pixel up to r = 20 mm, and 5% too bright everywhere (its thick exit pupil
        // is larger than the real lens's opening seen from the film).
        EXPECT_LT(e[i].maxErrorMm, 0.075) << e[i].filmRadius;
        EXPECT_GT(e[i].illuminationRatio, 1.04) << e[i].filmRadius;
        EXPECT_LT(e[i].illuminationRatio, 1.07) << e[i].filmRadius;
    }
    EXPECT_EQ(c.describe().at("thickLensShareOfFilm"), "0");
    EXPECT_FALSE(c.lensModes().usesThick());
}

TEST(AutoLensMode, TelephotoAtF11UsesTheThickLensEverywhereOnASmallFrameButNotOnALargeOne) {
    const RealisticCamera small(params("telephoto.250mm.dat", 11, LensMode::Auto), {}, 240, 160, 0.5);
    EXPECT_FALSE(small.lensModes().usesExact());
    EXPECT_EQ(small.pupilBounds().radiusCount(), 0) << "no exit-pupil bounds for a lens never traced exactly";
    for (const ThickLensFilmError& e : small.thickLensErrors()) EXPECT_NEAR(e.illuminationRatio, 1.0, 0.025);
    // 2400 x 1600: 15 um pixels, and the telephoto's 7-70 um errors no longer fit under half of one.
    const RealisticCamera large(params("telephoto.250mm.dat", 11, LensMode::Auto), {}, 2400, 1600, 0.5);
    EXPECT_TRUE(large.lensModes().usesExact());
    EXPECT_GT(large.pupilBounds().radiusCount(), 0);
}

TEST(AutoLensMode, TheFilmIsSplitOnlyWhereTheThickLensCoversNineTenthsOfIt) {
    // 480 x 320: the thick lens fits out to r = 17.8 mm, 91% of the film: thick there, exact beyond.
    const RealisticCamera split(params("telephoto.250mm.dat", 11, LensMode::Auto), {}, 480, 320, 0.5);
    EXPECT_EQ(split.describe().at("lensModelByFilmRadius"), "thick for r < 17.8 mm, exact beyond");
    EXPECT_EQ(split.describe().at("thickLensShareOfFilm"), "0.91");
    EXPECT_TRUE(split.lensModes().thickAt(17.0));
    EXPECT_FALSE(split.lensModes().thickAt(19.0));
    // 960 x 640: it fits to r = 13.8 mm only, 78% of the film: exact everywhere.
    const RealisticCamera whole(params("telephoto.250mm.dat", 11, LensMode::Auto), {}, 960, 640, 0.5);
    EXPECT_EQ(whole.describe().at("thickLensShareOfFilm"), "0.784");
    EXPECT_FALSE(whole.lensModes().usesThick());
}

TEST(AutoLensMode, AccurateAndApproximateModesKeepOneModelEverywhere) {
    const RealisticCamera accurate(params("dgauss.50mm.dat", 4, LensMode::Exact), {}, 240, 160, 0.5);
    EXPECT_FALSE(accurate.lensModes().usesThick());
    EXPECT_EQ(accurate.pupilBounds().radiusCount(), 64);
    EXPECT_TRUE(accurate.thickLensErrors().empty());
    const RealisticCamera approximate(params("dgauss.50mm.dat", 4, LensMode::Thick), {}, 240, 160, 0.5);
    EXPECT_FALSE(approximate.lensModes().usesExact());
    EXPECT_EQ(approximate.pupilBounds().radiusCount(), 0);
}

TEST(AutoLensMode, ACropWindowPreparesOnlyTheFilmRadiiItReaches) {
    // The top-right corner tenth of the frame: film radii from about 17 to 22 mm.
    RealisticParams p = params("fisheye.10mm.dat", 5.6, LensMode::Auto);
    p.crop = {0.9, 1.0, 0.0, 0.1};
    const RealisticCamera c(p, {}, 240, 160, 0.5);
    EXPECT_GT(c.minFilmRadius(), 16.0);
    EXPECT_LT(c.maxFilmRadius(), 22.0);
    EXPECT_GE(c.thickLensErrors().front().filmRadius, c.minFilmRadius());
    EXPECT_FALSE(c.lensModes().usesThick());
    EXPECT_GE(c.pupilBounds().minFilmRadius(), c.minFilmRadius() - c.pupilBounds().radiusStep);
    // The whole frame measures 64 radii over 0-21.8 mm; the ring takes those it spans, one more
    // at each end.
    const ExitPupilBounds& b = c.pupilBounds();
    EXPECT_NEAR(b.radiusStep * 63, 0.5 * std::hypot(36.0, 24.0), 0.4);  // and the pixel filter's reach
    EXPECT_LE(b.radiusCount(), std::ceil((c.maxFilmRadius() - c.minFilmRadius()) / b.radiusStep) + 2);
    EXPECT_LT(b.radiusCount(), 20);
}

TEST(AutoLensMode, TheSceneCropWindowReachesTheCameraOfARender) {
    test::TempDir dir;
    const std::string scene = dir.write("crop.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 4 \"string mode\" \"auto\"\n") +
        "Film \"image\" \"float cropwindow\" [0.45 0.55 0.45 0.55]\nWorldBegin\nWorldEnd\n");
    const RenderOutput full = test::render(dir.write("full.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 4 \"string mode\" \"accurate\"\n") +
        "Film \"image\"\nWorldBegin\nWorldEnd\n"), 100, 100, 1);
    EXPECT_EQ(full.metadata.at("exitPupilBoundsRadii"), "64");
    const RenderOutput crop = test::render(scene, 100, 100, 1);
    EXPECT_EQ(crop.metadata.at("mode"), "auto");
    EXPECT_EQ(crop.metadata.at("exitPupilBoundsRadii"), "0") << "the centre of a 50 mm lens needs no exact trace";
    EXPECT_EQ(crop.metadata.at("lensModelByFilmRadius").rfind("thick for 0 <= r <= ", 0), 0u)
        << crop.metadata.at("lensModelByFilmRadius");
    EXPECT_EQ(crop.metadata.at("autoThresholdPixels"), "0.5");
    EXPECT_FALSE(crop.metadata.at("thickLensErrorPixels").empty());
}

TEST(AutoLensMode, ACropOverrideInTheRenderSettingsReachesTheCamera) {
    test::TempDir dir;
    const std::string scene = dir.write("corner.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 4 \"string mode\" \"auto\"\n") +
        "Film \"image\" \"float cropwindow\" [0.9 1 0 0.1]\nWorldBegin\nWorldEnd\n");
    RenderSettings centre;
    centre.crop = std::array<double, 4>{0.45, 0.55, 0.45, 0.55};  // overrides the scene's corner window
    const RenderOutput out = test::render(scene, 100, 100, 1, centre);
    EXPECT_EQ(out.metadata.at("exitPupilBoundsRadii"), "0") << "the camera prepared the scene's corner, not the centre";
    EXPECT_EQ(out.metadata.at("lensModelByFilmRadius").rfind("thick for 0 <= r <= ", 0), 0u)
        << out.metadata.at("lensModelByFilmRadius");
}

// A fine checkerboard wall in the plane of focus, 5.5 m ahead, under a uniform sky, through the
// telephoto at f/11 on a 36 x 24 mm film; a 0.1-pixel threshold splits the film at r = 18.3 mm.
constexpr int kWallWidth = 96, kWallHeight = 64;
constexpr double kWallThreshold = 0.1;

std::string telephotoWall(const std::string& mode) {
    return test::courseCamera("telephoto.250mm.dat", "\"float fstop\" 11 \"float focaldistance\" ") +
           "5500 \"float filmdiagonal\" 43.267 \"string mode\" \"" + mode + "\" \"float autothreshold\" " + std::to_string(kWallThreshold) + "\n"
           "Film \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\" \"integer maxdepth\" 1\n"
           "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
           "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 720 \"float vscale\" 720 \"rgb tex1\" [0.9 0.9 0.9] "
           "\"rgb tex2\" [0.1 0.1 0.1]\nMaterial \"matte\" \"texture Kd\" \"c\"\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-9 -9 5.5  9 -9 5.5  9 9 5.5  -9 9 5.5] "
           "\"float uv\" [0 0 1 0 1 1 0 1]\nWorldEnd\n";
}

TEST(AutoLensMode, AutoImageIsTheApproximateOneWhereThickAndTheAccurateOneWhereExact) {
    test::TempDir dir;
    const auto render = [&](const std::string& mode) {
        return test::render(dir.write(mode + ".pbrt", telephotoWall(mode)), kWallWidth, kWallHeight, 4).image;
    };
    const Image accurate = render("exact"), approximate = render("thick"), automatic = render("auto");
    RealisticParams p = realisticParams(test::lensPath("telephoto.250mm.dat"), 11, 5500);
    p.filmDiagonalMm = 43.267;
    p.mode = LensMode::Auto;
    p.autoThresholdPixels = kWallThreshold;
    const RealisticCamera camera(p, {}, kWallWidth, kWallHeight, 0.5);
    ASSERT_EQ(camera.describe().at("lensModelByFilmRadius"), "thick for r < 18.3 mm, exact beyond");
    int thickPixels = 0, exactPixels = 0, thickSame = 0, exactSame = 0, thickDiffersFromAccurate = 0;
    for (int y = 0; y < kWallHeight; ++y)
        for (int x = 0; x < kWallWidth; ++x) {
            // A box-filtered pixel takes samples from its own square only: all four corners on one side.
            int thickCorners = 0;
            for (int c = 0; c < 4; ++c) {
                double fx, fy;
                camera.filmPoint(x + (c & 1), y + (c >> 1), fx, fy);
                thickCorners += camera.lensModes().thickAt(std::hypot(fx, fy));
            }
            const float a = test::lum(automatic, x, y);
            if (thickCorners == 4) {
                ++thickPixels;
                thickSame += a == test::lum(approximate, x, y);
                thickDiffersFromAccurate += a != test::lum(accurate, x, y);
            } else if (thickCorners == 0) {
                ++exactPixels;
                exactSame += a == test::lum(accurate, x, y);
            }
        }
    EXPECT_GT(thickPixels, 5000);  // of 6144
    EXPECT_GT(exactPixels, 200);   // the corners
    EXPECT_EQ(thickSame, thickPixels);
    EXPECT_EQ(exactSame, exactPixels);
    EXPECT_GT(thickDiffersFromAccurate, thickPixels / 2) << "the two models must differ for the check to mean anything";
}

TEST(AutoLensMode, ModeAutoIsAcceptedAsAnOverrideAndABadModeNamesTheChoices) {
    test::TempDir dir;
    const std::string scene = dir.write("m.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 8\nFilm \"image\"\nWorldBegin\nWorldEnd\n"));
    RenderSettings s;
    s.camera.mode = "auto";  // what the CLI's --mode and the API's "mode" pass on
    EXPECT_EQ(test::render(scene, 16, 16, 1, s).metadata.at("mode"), "auto");
    s.camera.mode = "fast";
    try {
        test::render(scene, 16, 16, 1, s);
        FAIL() << "mode \"fast\" was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("mode must be exact|thick|auto, got \"fast\""), std::string::npos)
            << e.what();
    }
    const std::string threshold = dir.write("t.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"string mode\" \"auto\" \"float autothreshold\" 0\n") +
        "Film \"image\"\nWorldBegin\nWorldEnd\n");
    EXPECT_THROW(test::render(threshold, 16, 16, 1), SceneError);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// One vocabulary for the lens model (exact, thick, auto, as the diagrams say it); round one's
// names still read, and come back under today's.
TEST(LensModeNames, ExactThickAutoWithRoundOnesNamesAccepted) {
    EXPECT_EQ(parseLensMode("exact"), LensMode::Exact);
    EXPECT_EQ(parseLensMode("thick"), LensMode::Thick);
    EXPECT_EQ(parseLensMode("auto"), LensMode::Auto);
    EXPECT_EQ(parseLensMode("accurate"), LensMode::Exact);
    EXPECT_EQ(parseLensMode("approximate"), LensMode::Thick);
    EXPECT_FALSE(parseLensMode("overlay").has_value());
    EXPECT_STREQ(lensModeName(LensMode::Exact), "exact");
    EXPECT_STREQ(lensModeName(LensMode::Thick), "thick");
}

}  // namespace
}  // namespace lenslab
