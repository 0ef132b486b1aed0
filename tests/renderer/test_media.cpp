// Participating media against closed forms: the transmittance of an absorbing slab, single
// scattering in a slab under a distant light (the exact integral along the view ray), and a white
// furnace (a non-absorbing medium under a uniform sky stays at the sky's radiance); the parser's
// media directives.
#include <gtest/gtest.h>

#include <cmath>

#include "RadianceProbe.h"
#include "TempDir.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// The slab 0 < z < depth between two wide disks that bound medium "m" and have no surface.
std::string slab(double depth) {
    return "Material \"interface\"\n"
           "AttributeBegin MediumInterface \"\" \"m\" Shape \"disk\" \"float radius\" 1000 AttributeEnd\n"
           "AttributeBegin MediumInterface \"m\" \"\" Shape \"disk\" \"float height\" " + std::to_string(depth) +
           " \"float radius\" 1000 AttributeEnd\n";
}

Vec3f meanRadiance(const test::RadianceProbe& probe, Vec3f o, Vec3f d, int n) {
    Vec3f sum;
    for (int i = 0; i < n; ++i) sum += probe.once(o, d, std::uint64_t(i));
    return sum / float(n);
}

// Looking through the slab at a uniform sky: exp(-sigma_t d) per channel, for the homogeneous
// medium (closed form per channel choice) and for a grid (delta tracking) of the same density.
TEST(Media, SlabTransmittanceIsBeerLambert) {
    const double depth = 0.7;
    const Vec3f expected{std::exp(-0.5f * 0.7f), std::exp(-1.0f * 0.7f), std::exp(-2.0f * 0.7f)};
    const std::string homogeneous = "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 1 2] \"rgb sigma_s\" [0 0 0]\n";
    // Cell centres at +-0.5 and +-1.5: constant density over the slab (trilinear to zero only outside).
    const std::string grid = "MakeNamedMedium \"m\" \"string type\" \"uniformgrid\" \"rgb sigma_a\" [0.5 1 2] \"rgb sigma_s\" [0 0 0]"
                             " \"point3 p0\" [-2 -2 -2] \"point3 p1\" [2 2 2] \"integer nx\" 4 \"integer ny\" 4 \"integer nz\" 4"
                             " \"float density\" [" + [] { std::string s; for (int i = 0; i < 64; ++i) s += " 1"; return s; }() + "]\n";
    for (const std::string& medium : {homogeneous, grid}) {
        test::TempDir dir;
        const test::RadianceProbe probe(test::probeScene(dir, test::kWhiteSky + medium + slab(depth)), IntegratorType::VolPath, 5);
        test::expectRelative(meanRadiance(probe, {0, 0, -1}, {0, 0, 1}, 100000), expected, 0.01, medium.c_str());
    }
}

// A measured medium by name ("preset", per mm): Merlot (Narasimhan et al. 2006) barely scatters
// (sigma_s under 3e-5), so the slab passes exp(-sigma_a d) of its measured absorption.
TEST(Media, PresetTakesTheMeasuredCoefficients) {
    test::TempDir dir;
    const std::string medium = "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"string preset\" \"Merlot\"\n";
    const test::RadianceProbe probe(test::probeScene(dir, test::kWhiteSky + medium + slab(0.7)), IntegratorType::VolPath, 5);
    const Vec3f expected{std::exp(-0.11632f * 0.7f), std::exp(-0.25191f * 0.7f), std::exp(-0.29434f * 0.7f)};
    test::expectRelative(meanRadiance(probe, {0, 0, -1}, {0, 0, 1}, 100000), expected, 0.01, "Merlot");
    const std::string unknown = test::sceneErrorOf(test::probeScene(dir, "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"string preset\" \"Marmite\"\n"));
    EXPECT_NE(unknown.find("s.pbrt:5"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("no measured medium is named \"Marmite\""), std::string::npos) << unknown;
}

// A slab 0 < z < d lit from above by a distant light of irradiance E, seen from below along a ray
// at angle alpha to the normal (mu = cos alpha). Single scattering (maxdepth 1) at height z, with
// the light attenuated over d - z and the scattered light over z / mu:
//   L = sigma_s p E / mu * integral_0^d exp(-sigma_t (d - z) - sigma_t z / mu) dz
//     = sigma_s p E / mu * exp(-sigma_t d) (exp(k d) - 1) / k,   k = sigma_t (1 - 1 / mu),
// p the Henyey-Greenstein phase at the scattering angle (cos theta = mu between the light's travel
// and the view ray's reverse).
TEST(Media, SlabSingleScatteringMatchesTheIntegral) {
    const double d = 1, sigmaS = 0.5, sigmaA = 0.1, g = 0.3, E = 2, alpha = 40 * M_PI / 180;
    const double mu = std::cos(alpha), sigmaT = sigmaS + sigmaA, k = sigmaT * (1 - 1 / mu);
    const double phase = (1 - g * g) / (4 * M_PI * std::pow(1 + g * g - 2 * g * mu, 1.5));
    const double expected = sigmaS * phase * E / mu * std::exp(-sigmaT * d) * (std::exp(k * d) - 1) / k;
    test::TempDir dir;
    const std::string world = "LightSource \"distant\" \"point from\" [0 0 1] \"point to\" [0 0 0] \"rgb L\" [2 2 2]\n"
                              "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.1 0.1]"
                              " \"rgb sigma_s\" [0.5 0.5 0.5] \"float g\" 0.3\n" + slab(d);
    const test::RadianceProbe probe(test::probeScene(dir, world), IntegratorType::VolPath, 1);
    const Vec3f view{float(std::sin(alpha)), 0, float(mu)};
    const Vec3f L = meanRadiance(probe, Vec3f{0, 0, -1} - view, view, 100000);
    test::expectRelative(L, {float(expected), float(expected), float(expected)}, 0.01, "single scattering");
}

// A white furnace: a sphere of non-absorbing medium (coloured scattering, forward phase) under a
// uniform sky of radiance 1 looks exactly like the sky, whatever the medium, when every order of
// scattering is followed.
TEST(Media, NonAbsorbingMediumInAFurnaceStaysAtOne) {
    std::string density;
    for (int i = 0; i < 27; ++i) density += " " + std::to_string(0.2 + 0.1 * ((i * 7) % 11));
    const std::string media[] = {
        "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [0.5 1 2] \"float g\" 0.5\n",
        "MakeNamedMedium \"m\" \"string type\" \"heterogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [1 2 3] \"float g\" -0.3"
        " \"point p0\" [-1 -1 -1] \"point p1\" [1 1 1] \"integer nx\" 3 \"integer ny\" 3 \"integer nz\" 3 \"float density\" [" +
            density + "]\n"};
    for (const std::string& medium : media) {
        test::TempDir dir;
        const std::string world = std::string(test::kWhiteSky) + medium +
                                  "Material \"interface\" MediumInterface \"m\" \"\" Shape \"sphere\" \"float radius\" 1\n";
        const test::RadianceProbe probe(test::probeScene(dir, world), IntegratorType::VolPath, 1000);
        test::expectRelative(meanRadiance(probe, {0.3f, 0, 3}, {0, 0, -1}, 20000), {1, 1, 1}, 0.01, medium.c_str());
    }
}

// The camera in a medium: a camera ray starts inside it (the absorbing slab's transmittance, seen
// from within it over the remaining depth).
TEST(Media, CameraTakesTheOutsideMediumAtCamera) {
    test::TempDir dir;
    const std::string options = "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [1 1 1] \"rgb sigma_s\" [0 0 0]\n"
                                "MediumInterface \"\" \"m\"\n";
    const std::string path = test::probeScene(dir, test::kWhiteSky + slab(1), options);
    const SceneDescription parsed = parseSceneFile(path);
    ASSERT_TRUE(parsed.camera.medium);
    const test::RadianceProbe probe(path, IntegratorType::VolPath, 5);
    EXPECT_NEAR(meanRadiance(probe, {0, 0, 0.25f}, {0, 0, 1}, 4).x, std::exp(-0.75), 1e-5);
}

// Without an Integrator directive each pbrt's own default: pbrt-v3 traces paths (the media
// ignored, with a warning), pbrt-v4 runs volpath (a pbrt-v4 material marks the file as pbrt-v4's).
TEST(Media, DefaultIntegratorIsEachPbrtsOwn) {
    test::TempDir dir;
    const std::string medium = "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n";
    const SceneDescription v3 = parseSceneFile(test::probeScene(dir, medium + slab(1)));
    ASSERT_EQ(v3.dialect, SceneDialect::PbrtV3);
    EXPECT_EQ(v3.integrator.type, IntegratorType::Path);
    ASSERT_FALSE(v3.warnings.empty());
    EXPECT_NE(v3.warnings.back().find("ignores the scene's participating media"), std::string::npos);
    const SceneDescription v4 = parseSceneFile(test::probeScene(dir, "Material \"diffuse\"\n" + medium + slab(1)));
    ASSERT_EQ(v4.dialect, SceneDialect::PbrtV4);
    EXPECT_EQ(v4.integrator.type, IntegratorType::VolPath);
    EXPECT_EQ(v4.integrator.maxDepth, 5);
    for (const std::string& w : v4.warnings) EXPECT_EQ(w.find("Integrator"), std::string::npos) << w;
    const SceneDescription v4Path = parseSceneFile(test::probeScene(dir, "Material \"diffuse\"\n" + medium + slab(1), "Integrator \"path\"\n"));
    EXPECT_EQ(v4Path.integrator.type, IntegratorType::Path);
}

TEST(Media, ParserChoosesVolpathAndNamesErrors) {
    test::TempDir dir;
    const std::string medium = "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n";
    const std::string bdpt = test::probeScene(dir, medium + slab(1), "Integrator \"bdpt\"\n");
    EXPECT_EQ(parseSceneFile(bdpt).integrator.type, IntegratorType::VolPath);
    const SceneDescription path = parseSceneFile(test::probeScene(dir, medium + slab(1), "Integrator \"path\"\n"));
    EXPECT_EQ(path.integrator.type, IntegratorType::Path);
    ASSERT_FALSE(path.warnings.empty());
    EXPECT_NE(path.warnings.back().find("ignores the scene's participating media"), std::string::npos);
    EXPECT_NE(test::sceneErrorOf(test::probeScene(dir, "MediumInterface \"fog\" \"\"\nShape \"sphere\"\n")).find("s.pbrt:6: Shape \"sphere\": unknown medium \"fog\""),
              std::string::npos);
    EXPECT_NE(test::sceneErrorOf(test::probeScene(dir, "MakeNamedMedium \"c\" \"string type\" \"rgbgrid\"\n")).find("s.pbrt:5: MakeNamedMedium \"c\": medium \"rgbgrid\" is not supported"),
              std::string::npos);
    EXPECT_NE(test::sceneErrorOf(test::probeScene(dir, "MakeNamedMedium \"g\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"float density\" [1]\n"))
                  .find("nx * ny * nz = 2"),
              std::string::npos);
}

}  // namespace
}  // namespace lenslab
