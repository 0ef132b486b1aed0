// Lights against closed forms: a white diffuse plane (albedo 1, radiance = irradiance / pi) under
// each kind of light, environment maps read and oriented as pbrt-v3 reads them, their sampling
// density, and the choice of lights by power.
#include <gtest/gtest.h>

#include <cmath>

#include "lights/LightSampler.h"
#include "RadianceProbe.h"
#include "TestScenes.h"
#include "prescription/Pi.h"

namespace lenslab {
namespace {

// A white matte plane, 2 km wide, at z = 0, facing +z.
const char* kWhitePlane = "Material \"matte\" \"rgb Kd\" [1 1 1]\n"
                          "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
                          "  \"point P\" [-1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0]\n";

std::string planeScene(const test::TempDir& dir, const std::string& lights) {
    return dir.write("plane.pbrt", std::string(test::kProbeHeader) + "WorldBegin\n" + lights + "\n" + kWhitePlane +
                                       "WorldEnd\n");
}

// Radiance of the white plane at (x, y, 0), seen from straight above.
double planeRadiance(const std::string& scene, double x, double y, int samples = 1,
                     IntegratorType type = IntegratorType::Whitted) {
    const test::RadianceProbe probe(scene, type, 5);
    return probe.mean({float(x), float(y), 1}, {0, 0, -1}, samples);
}

std::string lightErrorOf(const std::string& scene) {
    try {
        test::render(scene, 4, 4, 1);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(InfiniteLight, WhitePlaneUnderUniformSkyHasRadianceL) {
    test::TempDir dir;
    const std::string scene = dir.write("sky.pbrt", std::string(test::kProbeHeader) +
        "Integrator \"path\" \"integer maxdepth\" 1\nWorldBegin\n"
        "LightSource \"infinite\" \"rgb L\" [0.35 0.35 0.35] \"rgb scale\" [2 2 2]\n" + kWhitePlane + "WorldEnd\n");
    EXPECT_NEAR(test::meanLum(test::render(scene, 8, 8, 64).image), 0.7, 0.007);
}

// An equirectangular map bright (2) on its upper half, the light-space +z hemisphere, dark below.
std::string halfBrightMap(const test::TempDir& dir) {
    const int w = 16, h = 8;
    std::vector<float> rgb(std::size_t(w) * h * 3, 0.0f);
    for (int i = 0; i < w * h / 2 * 3; ++i) rgb[i] = 2.0f;
    const std::string path = dir.path() + "/half.exr";
    test::writeImage(path, w, h, rgb);
    return path;
}

TEST(EnvironmentMap, HalfBrightHalfDarkLightsPlanesByTheirFacing) {
    test::TempDir dir;
    halfBrightMap(dir);
    // Rotating the map turns the bright hemisphere from straight above (radiance 2) to the side
    // (half of the cosine-weighted hemisphere: 1) to below (0).
    const double expected[] = {2, 1, 0};
    const int degrees[] = {0, 90, 180};
    for (int i = 0; i < 3; ++i) {
        const std::string scene = planeScene(dir, "AttributeBegin\nRotate " + std::to_string(degrees[i]) +
            " 1 0 0\nLightSource \"infinite\" \"string mapname\" \"half.exr\"\nAttributeEnd\n");
        EXPECT_NEAR(planeRadiance(scene, 0.3, -0.2, 4000, IntegratorType::DirectLighting), expected[i], 0.02)
            << degrees[i] << " degrees";
        EXPECT_NEAR(planeRadiance(scene, 0.3, -0.2, 20000, IntegratorType::Path), expected[i], 0.02)
            << degrees[i] << " degrees";
    }
}

// A 4 x 2 map whose texel (x, y) holds x + 1 + 10 y.
std::string numberedMap(const test::TempDir& dir) {
    std::vector<float> rgb;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c) rgb.push_back(float(x + 1 + 10 * y));
    const std::string path = dir.path() + "/numbered.exr";
    test::writeImage(path, 4, 2, rgb);
    return path;
}

TEST(EnvironmentMap, OrientedAsPbrt) {
    test::TempDir dir;
    const std::string map = numberedMap(dir);
    const auto light = test::lightFrom("infinite", {test::stringParam("mapname", map), test::rgbParam("L", {2, 2, 2})});
    // Columns: phi = atan2(y, x) / 2 pi; rows: theta from +z. The map's value times L.
    const auto seen = [&](const Light& l, Vec3f d) { return l.emitted(nullptr, normalize(d)).x; };
    EXPECT_FLOAT_EQ(seen(*light, {1, 1, 2}), 2 * 1);       // phi 45, upper
    EXPECT_FLOAT_EQ(seen(*light, {0, 1, -0.3f}), 2 * 12);  // phi 90, lower
    EXPECT_FLOAT_EQ(seen(*light, {-1, -0.1f, 0.2f}), 2 * 3);
    EXPECT_FLOAT_EQ(seen(*light, {0.3f, -1, -0.2f}), 2 * 14);
    // The light's transform turns the map: Rotate 90 about x takes light-space (0, 1, -0.3) to
    // world (0, 0.3, 1).
    const auto turned = test::lightFrom("infinite", {test::stringParam("mapname", map)}, rotate(90, 1, 0, 0));
    EXPECT_FLOAT_EQ(seen(*turned, {0, 0.3f, 1}), 12);
    EXPECT_FLOAT_EQ(seen(*turned, {0.5f, -0.5f, 1}), 1);  // light-space (0.5, 1, 0.5): phi 63, upper
}

TEST(EnvironmentMap, EightBitFilesAreDecodedFromSrgb) {
    test::TempDir dir;
    const std::string png = dir.path() + "/grey.png", exr = dir.path() + "/grey.exr";
    test::writeImage(png, 2, 1, std::vector<float>(6, 128.0f / 255));
    test::writeImage(exr, 2, 1, std::vector<float>(6, 0.5f));
    const auto fromPng = test::lightFrom("infinite", {test::stringParam("mapname", png)});
    const auto fromExr = test::lightFrom("infinite", {test::stringParam("mapname", exr)});
    EXPECT_NEAR(fromPng->emitted(nullptr, {0, 0, 1}).x, std::pow((128.0 / 255 + 0.055) / 1.055, 2.4), 1e-5);
    EXPECT_FLOAT_EQ(fromExr->emitted(nullptr, {0, 0, 1}).x, 0.5f);
}

TEST(EnvironmentMap, SamplingDensityIntegratesToOneAndMatchesSamples) {
    test::TempDir dir;
    const int w = 32, h = 16;
    std::vector<float> rgb;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float v = (x == 5 && y == 4) ? 500.0f : 0.1f + 0.05f * float(y) + 0.01f * float(x);
            rgb.insert(rgb.end(), {v, v * 0.8f, v * 0.6f});
        }
    test::writeImage(dir.path() + "/sun.exr", w, h, rgb);
    const auto light = test::lightFrom("infinite", {test::stringParam("mapname", dir.path() + "/sun.exr")},
                                       rotate(30, 0, 1, 1));
    const Vec3f p{0.2f, 0.1f, 0.3f};

    // The density over the sphere, integrated on a fine (theta, phi) grid in world space.
    double total = 0, exactRadiance = 0;
    const int nt = 720, np = 1440;
    for (int i = 0; i < nt; ++i) {
        const double theta = (i + 0.5) * kPi / nt;
        for (int j = 0; j < np; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / np;
            const Vec3f d{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                          float(std::cos(theta))};
            const double dOmega = std::sin(theta) * (kPi / nt) * (2 * kPi / np);
            total += light->pdf(p, d, nullptr) * dOmega;
            exactRadiance += luminance(light->emitted(nullptr, d)) * dOmega;
        }
    }
    EXPECT_NEAR(total, 1.0, 0.005);

    // Samples: their pdf is pdf() in their direction, their radiance emitted() there, and
    // radiance / pdf estimates the integral of the radiance over the sphere.
    Pcg32 rng(7);
    double estimate = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
        LightSample s;
        ASSERT_TRUE(light->sample(p, rng.uniform(), rng.uniform(), s));
        EXPECT_NEAR(s.pdf, light->pdf(p, s.wi, nullptr), 2e-3 * s.pdf);
        EXPECT_EQ(luminance(s.radiance), luminance(light->emitted(nullptr, s.wi)));
        estimate += luminance(s.radiance) / s.pdf;
    }
    EXPECT_NEAR(estimate / n, exactRadiance, 0.01 * exactRadiance);
    // pbrt-v3's power: the map's mean through a disc of the scene's radius.
    light->setSceneBounds({0, 0, 0}, 2);
    double mean = 0;
    for (std::size_t i = 0; i < rgb.size(); i += 3) mean += luminance({rgb[i], rgb[i + 1], rgb[i + 2]});
    mean /= w * h;
    EXPECT_NEAR(luminance(light->power()), kPi * 4 * mean, 1e-3 * kPi * 4 * mean);
}

TEST(EnvironmentMap, MissingOrUnreadableMapNamesTheFile) {
    test::TempDir dir;
    const std::string missing = planeScene(dir, "LightSource \"infinite\" \"string mapname\" \"nosky.exr\"");
    EXPECT_NE(lightErrorOf(missing).find("nosky.exr"), std::string::npos) << lightErrorOf(missing);
    dir.write("broken.hdr", "this is not an image");
    const std::string broken = planeScene(dir, "LightSource \"infinite\" \"string mapname\" \"broken.hdr\"");
    const std::string e = lightErrorOf(broken);
    EXPECT_NE(e.find("broken.hdr"), std::string::npos) << e;
    EXPECT_NE(e.find("plane.pbrt:5"), std::string::npos) << e;
}

TEST(Lights, UnknownTypeAndBadConeAreNamed) {
    test::TempDir dir;
    const std::string laser = planeScene(dir, "LightSource \"laser\"");
    EXPECT_NE(lightErrorOf(laser).find("light \"laser\" is not supported"), std::string::npos) << lightErrorOf(laser);
    const std::string cone = planeScene(dir, "LightSource \"spot\" \"float coneangle\" 10 \"float conedeltaangle\" 20");
    EXPECT_NE(lightErrorOf(cone).find("conedeltaangle"), std::string::npos) << lightErrorOf(cone);
}

TEST(PointLight, IrradianceIsIntensityTimesCosineOverDistanceSquared) {
    test::TempDir dir;
    const std::string scene = planeScene(dir, "AttributeBegin\nTranslate 0.5 0 0\n"
        "LightSource \"point\" \"point from\" [0 0 2] \"rgb I\" [3 3 3] \"rgb scale\" [2 2 2]\nAttributeEnd");
    for (double x : {0.5, 2.0, -1.0}) {
        const double dx = x - 0.5, d2 = dx * dx + 4, cosine = 2 / std::sqrt(d2);
        EXPECT_NEAR(planeRadiance(scene, x, 0), 6 * cosine / d2 / kPi, 1e-5) << x;
    }
}

// pbrt-v3 names the falloff band "conedeltaangle" (default 5 degrees): with 10 the falloff
// starts at 20 degrees, so 25 degrees lies inside it.
TEST(SpotLight, FalloffAtKnownAngles) {
    test::TempDir dir;
    const std::string scene = planeScene(dir,
        "LightSource \"spot\" \"point from\" [0 0 2] \"point to\" [0 0 0] \"float coneangle\" 30 "
        "\"float conedeltaangle\" 10 \"rgb I\" [5 5 5]");
    const auto radiance = [](double degrees, double falloff) {
        const double c = std::cos(degrees * kPi / 180), d2 = 4 / (c * c);
        return 5 * falloff * c / d2 / kPi;
    };
    const auto at = [](double degrees) { return 2 * std::tan(degrees * kPi / 180); };
    const double c25 = std::cos(25 * kPi / 180), c30 = std::cos(30 * kPi / 180), c20 = std::cos(20 * kPi / 180);
    const double partial = std::pow((c25 - c30) / (c20 - c30), 4);
    EXPECT_NEAR(planeRadiance(scene, at(10), 0), radiance(10, 1), 1e-5);
    EXPECT_NEAR(planeRadiance(scene, 0, at(25)), radiance(25, partial), 1e-5);
    EXPECT_GT(partial, 0.05);
    EXPECT_LT(partial, 0.95);
    EXPECT_EQ(planeRadiance(scene, at(35), 0), 0.0);
}

TEST(DistantLight, LightsThePlaneByTheCosine) {
    test::TempDir dir;
    const std::string scene = planeScene(dir,
        "LightSource \"distant\" \"point from\" [1 0 1] \"point to\" [0 0 0] \"rgb L\" [2 2 2] \"rgb scale\" [1.5 1.5 1.5]");
    EXPECT_NEAR(planeRadiance(scene, 3, -7), 3 * std::sqrt(0.5) / kPi, 1e-5);
}

TEST(GoniometricLight, DiagramScalesIntensityAboutLightSpaceY) {
    test::TempDir dir;
    // Upper row (theta < 90 degrees from +y) 4, lower row 1; columns alike.
    test::writeImage(dir.path() + "/gonio.exr", 2, 2, {4, 4, 4, 4, 4, 4, 1, 1, 1, 1, 1, 1});
    const auto light = test::lightFrom("goniometric", {test::stringParam("mapname", dir.path() + "/gonio.exr"),
                                                       test::rgbParam("I", {3, 3, 3})},
                                       translate(1, 0, 0));
    LightSample s;
    ASSERT_TRUE(light->sample({1, 5, 0}, 0.5f, 0.5f, s));  // straight up from the light
    EXPECT_NEAR(s.radiance.x, 3 * 4 / 25.0, 1e-6);
    EXPECT_NEAR(s.wi.y, -1, 1e-6);
    ASSERT_TRUE(light->sample({1, -2, 0.1f}, 0.5f, 0.5f, s));
    EXPECT_NEAR(s.radiance.x, 3 * 1 / (4 + 0.01), 1e-5);
    EXPECT_NEAR(luminance(light->power()), 4 * kPi * 3 * 2.5, 1e-4);
}

TEST(ProjectionLight, ProjectsTheImageAlongZ) {
    test::TempDir dir;
    // A 2 x 1 slide, left texel red, right texel green; aspect 2 spans x in [-2, 2] * tan(fov/2).
    test::writeImage(dir.path() + "/slide.png", 2, 1, {1, 0, 0, 0, 1, 0});
    const auto light = test::lightFrom("projection", {test::stringParam("mapname", dir.path() + "/slide.png"),
                                                      test::floatParam("fov", 90), test::rgbParam("I", {2, 2, 2})});
    LightSample s;
    ASSERT_TRUE(light->sample({0.5f, 0, 1}, 0, 0, s));  // x / z = 0.5: right half
    EXPECT_NEAR(s.radiance.y, 2 / 1.25, 1e-5);
    EXPECT_EQ(s.radiance.x, 0);
    ASSERT_TRUE(light->sample({-1.5f, 0.5f, 1}, 0, 0, s));  // left half
    EXPECT_NEAR(s.radiance.x, 2 / (2.25 + 0.25 + 1), 1e-5);
    EXPECT_FALSE(light->sample({2.5f, 0, 1}, 0, 0, s));  // beyond the slide's edge
    EXPECT_FALSE(light->sample({0, 0.5f, -1}, 0, 0, s));  // behind the projector
    EXPECT_FALSE(light->sample({0, 1.5f, 1}, 0, 0, s));   // above the slide (y spans [-1, 1])
}

// One bright light (I = 100) among 99 dim ones (I = 1): power selection picks the bright one with
// probability 100 / 199.
std::string manyLights(const test::TempDir& dir) {
    std::string lights = "LightSource \"point\" \"point from\" [0 0 1] \"rgb I\" [100 100 100]\n";
    for (int i = 0; i < 99; ++i) {
        const double a = 2 * kPi * i / 99;
        lights += "LightSource \"point\" \"point from\" [" + std::to_string(std::cos(a)) + " " +
                  std::to_string(std::sin(a)) + " 1] \"rgb I\" [1 1 1]\n";
    }
    return planeScene(dir, lights);
}

TEST(LightSelection, ProbabilitiesFollowPower) {
    test::TempDir dir;
    SceneDescription scene = parseSceneFile(manyLights(dir));
    const SceneGeometry geometry(scene);
    const LightSampler sampler(geometry.lights());
    ASSERT_EQ(geometry.lights().size(), 100u);
    EXPECT_NEAR(sampler.probability(*geometry.lights()[0]), 100.0 / 199, 1e-6);
    EXPECT_NEAR(sampler.probability(*geometry.lights()[50]), 1.0 / 199, 1e-7);
    int bright = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        float pmf;
        const Light* chosen = sampler.choose((i + 0.5f) / n, pmf);
        EXPECT_FLOAT_EQ(pmf, sampler.probability(*chosen));
        bright += chosen == geometry.lights()[0].get();
    }
    EXPECT_NEAR(double(bright) / n, 100.0 / 199, 1e-4);
}

TEST(LightSelection, BrightLightAmongDimOnesIsNotDrownedInNoise) {
    test::TempDir dir;
    const test::RadianceProbe probe(manyLights(dir), IntegratorType::Path, 1);
    // Each light's share of the plane's radiance at the origin: I cos / (pi d^2).
    const double bright = 100 / kPi, dim = std::sqrt(0.5) / (2 * kPi);
    const double total = bright + 99 * dim;
    // Choosing uniformly, one sample is 100 times one light's share: its variance.
    const double uniformVariance = 100 * (bright * bright + 99 * dim * dim) - total * total;
    double sum = 0, sum2 = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        const double v = luminance(probe.once({0, 0, 1}, {0, 0, -1}, std::uint64_t(i)));
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n, variance = sum2 / n - mean * mean;
    EXPECT_NEAR(mean, total, 0.02 * total);
    EXPECT_LT(variance, 0.01 * uniformVariance) << variance << " vs " << uniformVariance;
}

}  // namespace
}  // namespace lenslab
