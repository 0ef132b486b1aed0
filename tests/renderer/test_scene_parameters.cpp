// The parser reads what pbrt-v3 reads: unknown or mistyped parameters are warnings naming file and
// line, pbrt-v2's and the spectral value types arrive as the right RGB, substitutes are announced,
// and the Film, ActiveTransform and progress options do what they say.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/SceneDescription.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// A camera looking down +z at an emitting square that fills the view: every pixel sees L.
std::string emitterScene(const std::string& options, const std::string& areaLight) {
    return "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
           "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8 " + options + "\n"
           "WorldBegin\nAttributeBegin\n" + areaLight + "\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-5 -5 3  -5 5 3  5 5 3  5 -5 3]\n"
           "AttributeEnd\nWorldEnd\n";
}

Vec3f centrePixel(const std::string& path) {
    const RenderOutput out = test::render(path, 8, 8, 4);
    const float* p = &out.image.rgb[(4 * 8 + 4) * 3];
    return {p[0], p[1], p[2]};
}

bool hasWarning(const SceneDescription& s, const std::string& text) {
    for (const auto& w : s.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

TEST(SceneParameters, UnknownAndMistypedParametersWarnWithFileAndLine) {
    test::TempDir dir;
    const std::string p = dir.write("w.pbrt",
                                    "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
                                    "Sampler \"stratified\" \"integer xsamples\" 2 \"integer ysamples\" 3\n"
                                    "  \"integer pixelsamples\" 64\n"
                                    "Film \"image\" \"float xresolution\" 99 \"integer yresolution\" 8\n"
                                    "WorldBegin\nShape \"sphere\" \"float radius\" 2 \"float sparkle\" 3\nWorldEnd\n");
    const SceneDescription s = parseSceneFile(p);
    EXPECT_EQ(s.pixelSamples, 6);                     // stratified: xsamples * ysamples
    EXPECT_EQ(s.film.xresolution, 1280);              // a float where pbrt-v3 wants an integer is not read
    EXPECT_TRUE(hasWarning(s, "w.pbrt:4: Sampler \"stratified\": ignoring parameter \"integer pixelsamples\""));
    EXPECT_TRUE(hasWarning(s, "w.pbrt:5: Film \"image\": ignoring parameter \"float xresolution\""));
    EXPECT_TRUE(hasWarning(s, "w.pbrt:7: Shape \"sphere\": ignoring parameter \"float sparkle\""));
}

TEST(SceneParameters, AreaIsAnotherNameForDiffuseAndColorForRgb) {
    test::TempDir dir;
    const Vec3f c = centrePixel(dir.write("a.pbrt", emitterScene("", "AreaLightSource \"area\" \"color L\" [2 3 4]")));
    EXPECT_NEAR(c.x, 2, 1e-4);
    EXPECT_NEAR(c.y, 3, 1e-4);
    EXPECT_NEAR(c.z, 4, 1e-4);
}

TEST(SceneParameters, SpectralValuesBecomeRgbWithCieLuminance) {
    test::TempDir dir;
    const auto emitted = [&](const std::string& value) {
        return centrePixel(dir.write("s.pbrt", emitterScene("", "AreaLightSource \"diffuse\" " + value)));
    };
    const auto Y = [](Vec3f c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
    // A constant spectrum has luminance 1 (pbrt-v3 normalises by the integral of y-bar).
    EXPECT_NEAR(Y(emitted("\"spectrum L\" [300 1 800 1]")), 1.0, 2e-3);
    // A box of height 10 over the ten 1 nm samples 550..559 (pbrt-v3 sums the spectrum at whole
    // nanometres): Y = 100 * mean(y-bar) / 106.857 with y-bar ~ 0.998 there (CIE 1931 table).
    EXPECT_NEAR(Y(emitted("\"spectrum L\" [549.5 0 549.51 10 559.49 10 559.5 0]")), 0.934, 0.02);
    // D65's white point in XYZ is sRGB white.
    const Vec3f white = emitted("\"xyz L\" [0.95047 1 1.08883]");
    EXPECT_NEAR(white.x, 1, 2e-3);
    EXPECT_NEAR(white.y, 1, 2e-3);
    EXPECT_NEAR(white.z, 1, 2e-3);
    // Blackbodies: 6504 K is close to white, 2700 K (tungsten) is orange; scale multiplies.
    const Vec3f d65 = emitted("\"blackbody L\" [6504 1]");
    EXPECT_NEAR(d65.x / d65.y, 1, 0.08);
    EXPECT_NEAR(d65.z / d65.y, 1, 0.12);
    const Vec3f warm = emitted("\"blackbody L\" [2700 2]");
    EXPECT_GT(warm.x, 1.3f * warm.y);
    EXPECT_GT(warm.y, 1.5f * warm.z);
    const Vec3f warmOne = emitted("\"blackbody L\" [2700 1]");
    EXPECT_NEAR(warm.y, 2 * warmOne.y, 1e-4);
    // A spectrum file beside the scene, with comments.
    dir.write("flat.spd", "# wavelength value\n400 0.5\n700 0.5 # flat\n");
    EXPECT_NEAR(Y(emitted("\"spectrum L\" \"flat.spd\"")), 0.5, 2e-3);
}

TEST(SceneParameters, SpectralErrorsNameTheProblem) {
    test::TempDir dir;
    const auto error = [&](const std::string& value) {
        try {
            parseSceneFile(dir.write("e.pbrt", emitterScene("", "AreaLightSource \"diffuse\" " + value)));
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(error("\"spectrum L\" [400 1 500]").find("(wavelength, value) pairs"), std::string::npos);
    EXPECT_NE(error("\"spectrum L\" [500 1 400 1]").find("wavelengths must increase"), std::string::npos);
    EXPECT_NE(error("\"spectrum L\" \"missing.spd\"").find("missing.spd"), std::string::npos);
    EXPECT_NE(error("\"blackbody L\" [-5 1]").find("temperature"), std::string::npos);
}

TEST(SceneParameters, FilmScaleAndMaxSampleLuminance) {
    test::TempDir dir;
    const std::string light = "AreaLightSource \"diffuse\" \"rgb L\" [2 3 4]";
    const Vec3f half = centrePixel(dir.write("h.pbrt", emitterScene("\"float scale\" 0.5", light)));
    EXPECT_NEAR(half.y, 1.5, 1e-4);
    const Vec3f clamped = centrePixel(dir.write("c.pbrt", emitterScene("\"float maxsampleluminance\" 1", light)));
    const double y = 0.2126 * 2 + 0.7152 * 3 + 0.0722 * 4;
    EXPECT_NEAR(clamped.x, 2 / y, 1e-4);
    EXPECT_NEAR(clamped.z, 4 / y, 1e-4);
}

TEST(SceneParameters, SubstitutesAreAnnouncedAndPbrtV2VolumesRefused) {
    test::TempDir dir;
    const std::string header = "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 4 \"integer yresolution\" 4\n";
    const SceneDescription bdpt = parseSceneFile(dir.write("b.pbrt", header + "Integrator \"bdpt\" \"integer maxdepth\" 7\n"
                                                                             "WorldBegin\nWorldEnd\n"));
    EXPECT_EQ(bdpt.integrator.type, IntegratorType::Path);
    EXPECT_EQ(bdpt.integrator.maxDepth, 7);
    EXPECT_TRUE(hasWarning(bdpt, "b.pbrt:3: Integrator \"bdpt\": integrator \"bdpt\" rendered by the path tracer"));
    const SceneDescription whitted = parseSceneFile(dir.write("wh.pbrt", header + "Integrator \"whitted\"\nWorldBegin\nWorldEnd\n"));
    EXPECT_EQ(whitted.integrator.type, IntegratorType::Whitted);
    const SceneDescription mitchell = parseSceneFile(
        dir.write("m.pbrt", header + "PixelFilter \"mitchell\" \"float B\" 0.5 \"float C\" 0.25\nWorldBegin\nWorldEnd\n"));
    EXPECT_EQ(mitchell.filter.type, FilterType::Mitchell);
    EXPECT_DOUBLE_EQ(mitchell.filter.B, 0.5);
    EXPECT_DOUBLE_EQ(mitchell.filter.C, 0.25);
    EXPECT_DOUBLE_EQ(mitchell.filter.xwidth, 2);
    try {
        // pbrt-v2's Volume directive (its media are pbrt-v3's MakeNamedMedium, test_media.cpp).
        parseSceneFile(dir.write("fog.pbrt", header + "WorldBegin\nVolume \"homogeneous\"\nWorldEnd\n"));
        ADD_FAILURE() << "a pbrt-v2 volume was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("fog.pbrt:4: Volume: participating media"), std::string::npos) << e.what();
    }
}

TEST(SceneParameters, MovingAreaLightsStandAtTheStartTimeWithAWarning) {
    test::TempDir dir;
    // The emitter moves 100 m aside by the end time: drawn where it starts, in view (docs/motion-blur.md).
    const std::string p = dir.write("mv.pbrt", emitterScene("", "ActiveTransform EndTime\nTranslate 100 0 0\nActiveTransform All\n"
                                                                "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]"));
    EXPECT_NEAR(centrePixel(p).y, 1, 1e-4);
    EXPECT_TRUE(hasWarning(parseSceneFile(p), "an area light cannot move during the exposure"));
    // Moved at shutter open instead: out of view.
    const std::string q = dir.write("mv2.pbrt", emitterScene("", "ActiveTransform StartTime\nTranslate 100 0 0\nActiveTransform All\n"
                                                                 "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]"));
    EXPECT_NEAR(centrePixel(q).y, 0, 1e-6);
}

TEST(SceneParameters, LoadingReportsProgressToTheEnd) {
    test::TempDir dir;
    const std::string p = dir.write("pr.pbrt", emitterScene("", "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]"));
    std::vector<double> seen;
    parseSceneFile(p, {false, [&](double f) { seen.push_back(f); }});
    ASSERT_FALSE(seen.empty());
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
    for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// Orthographic: an emitting ball of radius 0.5 spans half of a [-1, 1] screen window at any distance.
TEST(OrthographicCamera, SilhouetteWidthDoesNotDependOnDistance) {
    test::TempDir dir;
    for (const char* distance : {"5", "50"}) {
        const std::string p = dir.write("o.pbrt", std::string("LookAt 0 0 0  0 0 1  0 1 0\n"
                                                              "Camera \"orthographic\" \"float screenwindow\" [-1 1 -1 1]\n"
                                                              "Film \"image\" \"integer xresolution\" 32 \"integer yresolution\" 32\n"
                                                              "WorldBegin\nAttributeBegin\nTranslate 0 0 ") + distance +
                                                      "\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                                      "Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\nWorldEnd\n");
        const RenderOutput out = test::render(p, 32, 32, 16);
        int lit = 0;
        for (int x = 0; x < 32; ++x) lit += test::lum(out.image, x, 16) > 0.5f;
        EXPECT_NEAR(lit, 16, 1) << "distance " << distance;
        EXPECT_NEAR(test::lum(out.image, 16, 16), 1.0f, 1e-4);
        EXPECT_NEAR(test::lum(out.image, 2, 16), 0.0f, 1e-6);
    }
}

// Perspective: an emitting ball of angular radius asin(0.1) 5 m ahead spans tan(asin(0.1)) /
// tan(15 degrees) = 0.375 of a 30-degree view (12 of 32 pixels); pbrt-v3's "halffov" 15 gives that
// view (ignored, the default 90 degrees would light 3).
TEST(PerspectiveCamera, HalfFovSetsHalfTheFieldOfView) {
    test::TempDir dir;
    const std::string p = dir.write("h.pbrt", "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float halffov\" 15\n"
                                              "Film \"image\" \"integer xresolution\" 32 \"integer yresolution\" 32\n"
                                              "WorldBegin\nAttributeBegin\nTranslate 0 0 5\n"
                                              "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                              "Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\nWorldEnd\n");
    const RenderOutput out = test::render(p, 32, 32, 16);
    int lit = 0;
    for (int x = 0; x < 32; ++x) lit += test::lum(out.image, x, 16) > 0.5f;
    EXPECT_NEAR(lit, 12, 1);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// Environment camera: azimuth across, polar angle from +y down; camera +z (forward) is a quarter
// of the way across the middle row, +y is the top row.
TEST(EnvironmentCamera, LatitudeLongitudeLayout) {
    test::TempDir dir;
    const std::string p = dir.write("env.pbrt", "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"environment\"\n"
                                                "Film \"image\" \"integer xresolution\" 64 \"integer yresolution\" 32\n"
                                                "WorldBegin\nMaterial \"matte\" \"rgb Kd\" [0 0 0]\n"
                                                "AreaLightSource \"diffuse\" \"rgb L\" [1 0 0]\n"
                                                "AttributeBegin\nTranslate 0 0 5\nShape \"sphere\" \"float radius\" 1\nAttributeEnd\n"
                                                "AreaLightSource \"diffuse\" \"rgb L\" [0 1 0]\n"
                                                "AttributeBegin\nTranslate 0 5 0\nShape \"sphere\" \"float radius\" 1\nAttributeEnd\nWorldEnd\n");
    const RenderOutput out = test::render(p, 64, 32, 4);
    const auto red = [&](int x, int y) { return out.image.rgb[(std::size_t(y) * 64 + x) * 3]; };
    const auto green = [&](int x, int y) { return out.image.rgb[(std::size_t(y) * 64 + x) * 3 + 1]; };
    EXPECT_NEAR(red(16, 16), 1, 1e-4);  // forward
    EXPECT_NEAR(red(48, 16), 0, 1e-6);  // backward
    EXPECT_NEAR(red(0, 16), 0, 1e-6);   // camera +x
    for (int x = 0; x < 64; x += 8) EXPECT_NEAR(green(x, 0), 1, 1e-4) << x;  // the +y pole spans the top row
    EXPECT_NEAR(green(16, 16), 0, 1e-6);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// A lens setting is blamed on where it came from: the scene's line, or the flag that overrode it.
TEST(LensSettingSources, ErrorsNameTheSceneLineOrTheOverridingFlag) {
    test::TempDir dir;
    const std::string p = dir.write("cam.pbrt", test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 1.2 ") +
                                                    "\nFilm \"image\"\nWorldBegin\nWorldEnd\n");
    const auto errorOf = [&](RenderSettings s) {
        s.scenePath = p;
        s.width = s.height = 8;
        s.spp = 1;
        try {
            renderScene(s);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    const std::string scene = errorOf({});
    EXPECT_NE(scene.find("cam.pbrt:2: Camera \"realistic\": fstop: f-number 1.2 is outside this lens's range f/2.02 to f/64"),
              std::string::npos)
        << scene;
    RenderSettings flag;
    flag.camera.fstop = Setting{0.7, "--fstop"};
    const std::string overridden = errorOf(flag);
    EXPECT_EQ(overridden.rfind("--fstop: f-number 0.7 is outside this lens's range", 0), 0u) << overridden;
    flag.camera.fstop = Setting{4, "--fstop"};
    EXPECT_EQ(errorOf(flag), "(no error)");
}

}  // namespace
}  // namespace lenslab
