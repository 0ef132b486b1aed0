// pbrt-v3's path, directlighting and whitted integrators against closed forms: a white diffuse
// plane (albedo 1: radiance = irradiance / pi) under a point light, under a uniform sky, under an
// emitting ceiling and under an emitting disk, and a mirror showing a lit wall.
#include <gtest/gtest.h>

#include <cmath>

#include "RadianceProbe.h"
#include "TempDir.h"
#include "TestScenes.h"
#include "prescription/Pi.h"

namespace lenslab {
namespace {

const IntegratorType kAll[] = {IntegratorType::Path, IntegratorType::DirectLighting, IntegratorType::Whitted};
const char* kIntegratorNames[] = {"path", "directlighting", "whitted"};

std::string square(double half, double z, const std::string& material) {
    const std::string h = std::to_string(half), zs = std::to_string(z);
    return material + "\nShape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-" + h + " -" + h + " " +
           zs + "  " + h + " -" + h + " " + zs + "  " + h + " " + h + " " + zs + "  -" + h + " " + h + " " + zs + "]\n";
}

const std::string kWhite = "Material \"matte\" \"rgb Kd\" [1 1 1]";

TEST(Integrators, DiffusePlaneUnderAPointLight) {
    test::TempDir dir;
    const std::string s = test::probeScene(dir, "LightSource \"point\" \"point from\" [0 0 2] \"rgb I\" [4 4 4]\n" +
                                         square(100, 0, kWhite));
    const double d2 = 1 + 4, expected = 4 * (2 / std::sqrt(d2)) / d2 / kPi;
    for (int i = 0; i < 3; ++i) {
        const test::RadianceProbe probe(s, kAll[i], 5);
        EXPECT_NEAR(probe.mean({1, 0, 1}, {0, 0, -1}, 4), expected, 1e-5) << kIntegratorNames[i];
    }
}

// A mirror floor (Kr 0.9) under a white ceiling that a point light between them lights from
// below. Looking down at the floor shows the ceiling: 0.9 times its radiance (its direct light:
// at maxdepth 2 path tracing stops before the light the mirror sends back up).
TEST(Integrators, MirrorShowsTheLitCeiling) {
    test::TempDir dir;
    const std::string s = test::probeScene(dir, "LightSource \"point\" \"point from\" [0 0 1] \"rgb I\" [4 4 4]\n" +
                                         square(100, 0, "Material \"mirror\" \"rgb Kr\" [0.9 0.9 0.9]") +
                                         square(100, 2, kWhite));
    const double x = 0.5, d2 = x * x + 1, ceiling = 4 * (1 / std::sqrt(d2)) / d2 / kPi;
    for (int i = 0; i < 3; ++i) {
        const test::RadianceProbe probe(s, kAll[i], 2);
        EXPECT_NEAR(probe.mean({float(x), 0, 1}, {0, 0, -1}, 4), 0.9 * ceiling, 1e-5) << kIntegratorNames[i];
    }
    // pbrt-v3's depth: maxdepth 1 shades the first surface only, and the mirror alone is black.
    EXPECT_EQ(test::RadianceProbe(s, IntegratorType::Whitted, 1).mean({float(x), 0, 1}, {0, 0, -1}, 4), 0.0);
    EXPECT_EQ(test::RadianceProbe(s, IntegratorType::DirectLighting, 1).mean({float(x), 0, 1}, {0, 0, -1}, 4), 0.0);
}

TEST(Integrators, WhitePlaneUnderUniformSkyHasRadianceL) {
    test::TempDir dir;
    const std::string s = test::probeScene(dir, "LightSource \"infinite\" \"rgb L\" [0.6 0.6 0.6]\n" + square(1000, 0, kWhite));
    for (int i = 0; i < 3; ++i) {
        const test::RadianceProbe probe(s, kAll[i], 5);
        EXPECT_NEAR(probe.mean({0.2f, 0.3f, 1}, {0, 0, -1}, 20000), 0.6, 0.006) << kIntegratorNames[i];
    }
}

// An emitting square ceiling (radiance 0.5, 20 x 20, 1 above the plane) over the white plane: the
// plane's radiance is 0.5 times the ceiling's view factor from the point below its centre, four
// times that of a 10 x 10 rectangle seen from below its corner. Whitted samples the ceiling by
// area alone, which is noisy: it gets more samples and a wider tolerance.
TEST(Integrators, EmittingCeilingOverWhitePlane) {
    test::TempDir dir;
    const std::string s = test::probeScene(dir, "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [0.5 0.5 0.5] "
                                     "\"bool twosided\" true\n" + square(10, 1, kWhite) + "AttributeEnd\n" +
                                     square(1000, 0, kWhite));
    const double a = 10, f = std::atan(a / std::sqrt(1 + a * a)) * a / std::sqrt(1 + a * a) / (2 * kPi) * 2;
    const double expected = 0.5 * 4 * f;
    const int samples[] = {20000, 20000, 200000};
    const double tolerance[] = {0.01, 0.01, 0.03};
    for (int i = 0; i < 3; ++i) {
        const test::RadianceProbe probe(s, kAll[i], 1);
        EXPECT_NEAR(probe.mean({0, 0, 0.5f}, {0, 0, -1}, samples[i]), expected, tolerance[i] * expected) << kIntegratorNames[i];
    }
}

// An emitting disk (radiance 2, radius 0.5) facing down from 1 above the white plane: the
// irradiance on its axis is pi L r^2 / (r^2 + h^2), the plane's radiance L r^2 / (r^2 + h^2) = 0.4.
TEST(Integrators, EmittingDiskOverWhitePlane) {
    test::TempDir dir;
    const std::string s = test::probeScene(dir, "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n"
                                     "Translate 0 0 1\nRotate 180 1 0 0\nShape \"disk\" \"float radius\" 0.5\n"
                                     "AttributeEnd\n" + square(1000, 0, kWhite));
    const double L = 2, r = 0.5, h = 1, expected = L * r * r / (r * r + h * h);
    for (int i = 0; i < 3; ++i) {
        const test::RadianceProbe probe(s, kAll[i], 1);
        EXPECT_NEAR(probe.mean({0, 0, 0.5f}, {0, 0, -1}, 20000), expected, 0.01 * expected) << kIntegratorNames[i];
    }
}

// The same through a render: the centre pixel of a camera looking straight down at the plane lit
// by a point light above it (the pixel spans +-0.04 m, where the radiance varies by 0.2%).
TEST(Integrators, RenderedPlaneUnderAPointLight) {
    test::TempDir dir;
    const std::string s = dir.write("r.pbrt", "LookAt 0 0 1  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
        "Integrator \"directlighting\" \"integer maxdepth\" 1\nPixelFilter \"box\"\nWorldBegin\n"
        "LightSource \"point\" \"point from\" [0 0 2] \"rgb I\" [4 4 4]\n" + square(100, 0, kWhite) + "WorldEnd\n");
    const RenderOutput out = test::render(s, 9, 9, 16);
    EXPECT_NEAR(test::lum(out.image, 4, 4), 4 / 4.0 / kPi, 0.005 * 4 / 4.0 / kPi);
    // Two pixels right: the field angle is atan(2 tan(20 deg) / 4.5), the plane point that far off.
    const double r = 2 * std::tan(20 * kPi / 180) / 4.5, d2 = r * r + 4;
    EXPECT_NEAR(test::lum(out.image, 6, 4), 4 * (2 / std::sqrt(d2)) / d2 / kPi, 0.01 * 4 / 4.0 / kPi);
}

// The volumetric path tracer follows a shadow ray hit by hit only where some surface is a bare
// medium boundary; without one, the any-hit query answers. The two must agree ray for ray: a plane
// half shadowed by a sphere, under a point light (a second sphere beyond it) and a sky, with and
// without a tiny boundary inside the opaque sphere, where no path reaches (it switches the
// hit-by-hit walk on, and leaves the scene's bounds, which the sky samples within, as they were),
// gives the same estimates, sample for sample.
TEST(Integrators, VolpathShadowRaysAnswerAlikeByAnyHitAndHitByHit) {
    const std::string world = kWhite + "\nLightSource \"point\" \"rgb I\" [4 4 4] \"point from\" [0.5 0.3 2]\n"
                              "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n" + square(3, 0, "") +
                              "AttributeBegin Translate 0 0 0.6 Shape \"sphere\" \"float radius\" 0.3 AttributeEnd\n"
                              // beyond the light, on the far side from the shadow rays it must not stop
                              "AttributeBegin Translate 0.75 0.55 3 Shape \"sphere\" \"float radius\" 0.3 AttributeEnd\n";
    const std::string boundary = "AttributeBegin Material \"interface\" Translate 0 0 0.6 "
                                 "Shape \"sphere\" \"float radius\" 0.001 AttributeEnd\n";
    test::TempDir dir;
    const test::RadianceProbe anyHit(test::probeScene(dir, world), IntegratorType::VolPath, 5);
    ASSERT_FALSE(anyHit.geometry().hasPassthroughSurfaces());
    const test::RadianceProbe walked(dir.write("b.pbrt", std::string(test::kProbeHeader) + "WorldBegin\n" + world + boundary + "WorldEnd\n"),
                                     IntegratorType::VolPath, 5);
    ASSERT_TRUE(walked.geometry().hasPassthroughSurfaces());
    int shadowed = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3f target{-1.5f + 0.0075f * float(i), -0.2f, 0};  // across the sphere's shadow
        const Vec3f o{0, 0, 5}, d = target - o;
        const Vec3f a = anyHit.once(o, d, std::uint64_t(i)), b = walked.once(o, d, std::uint64_t(i));
        EXPECT_EQ(a.x, b.x) << "sample " << i;
        EXPECT_EQ(a.z, b.z) << "sample " << i;
        shadowed += luminance(a) < 0.4f;  // the sky alone (0.3) against the sky and the light (0.55)
    }
    EXPECT_GT(shadowed, 20);   // some of the plane lies in the shadow
    EXPECT_LT(shadowed, 380);  // and some in the light
}

}  // namespace
}  // namespace lenslab
