// Lens flare in whole frames: off and auto without a bright emitter leave the image as it was, bit
// for bit; auto models a bright light in the frame (a point or a distant light, a small area light,
// a bright texel of an environment map) and none behind the camera, far outside the frame or
// hidden behind an object; ghosts through MgF2 take its colour (more blue and red than green);
// the paraxial model approaches the exact one where its approximation holds; bad settings are
// refused naming them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "RadianceProbe.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// dgauss.50mm at f/8 on a full-frame film, looking down +z over grey ground 1.5 m below, lit by a dim sky.
std::string flareScene(const test::TempDir& dir, const std::string& lights, const std::string& lens = "dgauss.50mm.dat") {
    return dir.write("flare.pbrt",
                     test::courseCamera(lens, "\"float fstop\" 8 \"float focaldistance\" 20000 \"float filmdiagonal\" 43.27") +
                         "\nFilm \"image\" \"integer xresolution\" 72 \"integer yresolution\" 48\n"
                         "Sampler \"sobol\" \"integer pixelsamples\" 2\nIntegrator \"directlighting\"\nWorldBegin\n"
                         "LightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\n" + lights +
                         "\nMaterial \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
                         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
                         "  \"point P\" [-200 -1.5 -10  200 -1.5 -10  200 -1.5 200  -200 -1.5 200]\nWorldEnd\n");
}

std::string pointLight(double x, double y, double z, double intensity) {
    return "LightSource \"point\" \"point from\" [" + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) +
           "] \"rgb I\" [" + std::to_string(intensity) + " " + std::to_string(intensity) + " " + std::to_string(intensity) + "]\n";
}

RenderOutput renderFlare(const std::string& scene, const std::string& ghosts, const std::string& model = "exact") {
    RenderSettings s;
    s.camera.ghosts = ghosts;
    s.camera.ghostModel = model;
    return test::render(scene, 72, 48, 2, s);
}

double total(const Image& im) {
    double sum = 0;
    for (float v : im.rgb) sum += v;
    return sum;
}

TEST(FlareFrames, OffAndAutoWithoutABrightEmitterChangeNoBit) {
    test::TempDir dir;
    // A light in the frame too dim to matter: 1e-3 W/sr at 20 m.
    const std::string scene = flareScene(dir, pointLight(1, 0.5, 20, 1e-3));
    const RenderOutput plain = test::render(scene, 72, 48, 2);
    for (const char* ghosts : {"off", "auto"}) {
        const RenderOutput out = renderFlare(scene, ghosts);
        EXPECT_EQ(out.image.rgb, plain.image.rgb) << ghosts;
        EXPECT_EQ(out.stats.flarePaths, 0) << ghosts;
        EXPECT_EQ(out.metadata.count("lensFlare"), 0u) << ghosts;
    }
}

TEST(FlareFrames, AutoModelsBrightEmittersInOrNearTheFrameOnly) {
    test::TempDir dir;
    const auto sources = [&](const std::string& lights) { return renderFlare(flareScene(dir, lights), "auto").stats.flareSources; };
    EXPECT_EQ(sources(pointLight(1, 0.5, 20, 5000)), 1);
    EXPECT_EQ(sources("LightSource \"distant\" \"point from\" [0.1 0.05 1] \"point to\" [0 0 0] \"rgb L\" [3 3 3]"), 1);
    EXPECT_EQ(sources("AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [20000 20000 20000]\nTranslate 1 0.5 30\n"
                      "Shape \"sphere\" \"float radius\" 0.1\nAttributeEnd\n"),
              1);
    EXPECT_EQ(sources(pointLight(1, 0.5, -20, 5000)), 0);  // behind the camera
    EXPECT_EQ(sources(pointLight(40, 0.5, 20, 5000)), 0);  // 63 degrees off the axis: far outside the frame
    EXPECT_EQ(sources(pointLight(1, 0.5, 20, 5000) +
                      "AttributeBegin\nMaterial \"matte\"\nTranslate 0.5 0.25 10\nShape \"sphere\" \"float radius\" 0.3\nAttributeEnd\n"),
              0);  // hidden behind a ball
    // The same bright light, asked for all ghosts or the five brightest.
    const std::string scene = flareScene(dir, pointLight(1, 0.5, 20, 5000));
    const RenderOutput all = renderFlare(scene, "all"), five = renderFlare(scene, "5"), off = renderFlare(scene, "off");
    EXPECT_EQ(all.stats.flarePaths, 45);
    EXPECT_EQ(five.stats.flarePaths, 5);
    EXPECT_GT(total(all.image), total(five.image));
    EXPECT_GT(total(five.image), total(off.image));
    EXPECT_NE(all.metadata.at("lensFlare").find("45 paths of 1 point light"), std::string::npos) << all.metadata.at("lensFlare");
}

// More bright lights than auto models (kMostFlareSources, 8): the brightest are kept. Two lights
// of 10^6 W/sr among eight of 5000: the ten's flare holds at least the two's (kept the dimmest
// eight, it would hold about 2% of it).
TEST(FlareFrames, AutoKeepsTheBrightestWhenMoreQualifyThanItModels) {
    test::TempDir dir;
    const auto flare = [&](const std::string& lights) {
        const std::string scene = flareScene(dir, lights);
        const RenderOutput on = renderFlare(scene, "auto"), off = renderFlare(scene, "off");
        EXPECT_EQ(on.stats.flareSources, std::min(8, int(std::count(lights.begin(), lights.end(), '\n'))));
        return total(on.image) - total(off.image);
    };
    const std::string bright = pointLight(-1.5, 0.8, 20, 1e6) + pointLight(1.5, -0.6, 20, 1e6);
    std::string dim;
    for (int i = 0; i < 8; ++i) dim += pointLight(-2 + 0.5 * i, 0.3 * (i % 3) - 0.3, 20, 5000);
    const double brightOnly = flare(bright), all = flare(dim + bright);
    EXPECT_GT(brightOnly, 0);
    EXPECT_GT(all, 0.95 * brightOnly);
}

// A 256 x 128 sky, black but for one texel (1.4 deg across) of radiance 10^5: one source.
TEST(FlareFrames, AutoModelsABrightTexelOfAnEnvironmentMap) {
    test::TempDir dir;
    std::vector<float> rgb(256 * 128 * 3, 0.0f);
    // Equirectangular: the texel at column 64 (phi 90 deg), row 64 (theta just past 90 deg) looks
    // along +y in light space; Rotate 90 about x turns that to +z, into the frame.
    for (int c = 0; c < 3; ++c) rgb[(64 * 256 + 64) * 3 + c] = 1e5f;
    test::writeImage(dir.path() + "/sun.exr", 256, 128, rgb);
    const std::string scene = flareScene(dir, "AttributeBegin\nRotate 90 1 0 0\nLightSource \"infinite\" \"string mapname\" \"sun.exr\"\nAttributeEnd\n");
    const RenderOutput out = renderFlare(scene, "auto");
    EXPECT_EQ(out.stats.flareSources, 1);
    EXPECT_NE(out.metadata.at("lensFlare").find("environment map"), std::string::npos) << out.metadata.at("lensFlare");
}

// MgF2 reflects least in the green: two reflections from it give a magenta ghost.
TEST(FlareFrames, CoatedGhostsTakeTheCoatingsColour) {
    test::TempDir dir;
    const std::string scene = flareScene(dir, "LightSource \"distant\" \"point from\" [0.1 0.05 1] \"point to\" [0 0 0] \"rgb L\" [3 3 3]");
    const Image off = renderFlare(scene, "off").image, on = renderFlare(scene, "all").image;
    double sum[3] = {0, 0, 0};
    for (std::size_t i = 0; i < on.rgb.size(); ++i) sum[i % 3] += on.rgb[i] - off.rgb[i];
    EXPECT_GT(sum[0], 1.3 * sum[1]);
    EXPECT_GT(sum[2], 1.3 * sum[1]);
}

// Near the axis and stopped down the paraxial ghosts are the exact ones: the same light within a
// few percent. (Wide open and far off axis they part: bench/README.md measures by how much.)
TEST(FlareFrames, ParaxialModelApproachesTheExactNearTheAxis) {
    test::TempDir dir;
    const std::string scene = flareScene(dir, "LightSource \"distant\" \"point from\" [0.02 0.01 1] \"point to\" [0 0 0] \"rgb L\" [3 3 3]");
    const double off = total(renderFlare(scene, "off").image);
    const double exact = total(renderFlare(scene, "all", "exact").image) - off;
    const double paraxial = total(renderFlare(scene, "all", "paraxial").image) - off;
    EXPECT_GT(exact, 0);
    EXPECT_NEAR(paraxial / exact, 1, 0.1);
}

TEST(FlareFrames, BadSettingsAreRefusedByName) {
    test::TempDir dir;
    const std::string scene = flareScene(dir, pointLight(1, 0.5, 20, 5000));
    const auto refusal = [&](const std::string& ghosts, const std::string& model, const std::string& path) {
        RenderSettings s;
        s.scenePath = path;
        s.camera.ghosts = ghosts;
        s.camera.ghostModel = model;
        try {
            checkRenderSettings(s);
            renderScene(s);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(refusal("many", "exact", scene).find("ghosts must be off, auto, all or a number"), std::string::npos);
    EXPECT_NE(refusal("0", "exact", scene).find("ghosts must be"), std::string::npos);
    EXPECT_NE(refusal("all", "fast", scene).find("ghost model must be exact or paraxial"), std::string::npos);
    const std::string pinhole = dir.write("pinhole.pbrt", "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 8 "
                                                          "\"integer yresolution\" 8\nWorldBegin\nWorldEnd\n");
    EXPECT_NE(refusal("all", "exact", pinhole).find("ghosts need a Camera \"realistic\""), std::string::npos);
    EXPECT_EQ(refusal("auto", "exact", pinhole), "(no error)");
}

}  // namespace
}  // namespace lenslab
