// pbrt-v4's subsurface material as a dielectric boundary over a scattering volume, against closed
// forms: a white furnace, the diffuse reflectance asked for (the albedo table against Chiang, Kutz
// & Burley's fit, and rendered), an absorbing slab's transmittance with its Fresnel factors; the
// parameter forms and their errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "RadianceProbe.h"
#include "TempDir.h"
#include "TestScenes.h"
#include "materials/Fresnel.h"
#include "materials/SubsurfaceAlbedo.h"

namespace lenslab {
namespace {

// The mean radiance over the disk a unit sphere at the origin shows to parallel rays along -z.
// Points uniform over the disk see the surface at angles weighted by cos: under a uniform sky of
// radiance 1 the mean is the sphere's diffuse (cosine-weighted hemispherical) reflectance.
Vec3f meanOverDisk(const test::RadianceProbe& probe, int n) {
    Vec3f sum;
    for (int i = 0; i < n; ++i) {
        // A Fibonacci spiral covers the disk evenly.
        const float r = std::sqrt((i + 0.5f) / n), phi = 2.39996323f * i;
        sum += probe.once({r * std::cos(phi), r * std::sin(phi), 3}, {0, 0, -1}, std::uint64_t(i));
    }
    return sum / float(n);
}

// The cosine-weighted mean over the hemisphere of the Fresnel reflectance from air into eta.
float diffuseFresnel(float eta) {
    double sum = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double mu = (i + 0.5) / n;
        sum += 2 * mu * fresnelDielectric(float(mu), 1.0f, eta) / n;
    }
    return float(sum);
}

TEST(Subsurface, AlbedoTableAtIndexOneMatchesChiangKutzBurley) {
    const SubsurfaceAlbedoTable table(1.0f);
    for (float reflectance : {0.05f, 0.2f, 0.4f, 0.6f, 0.8f, 0.95f}) {
        const float albedo = chiangSingleScatteringAlbedo(reflectance);
        EXPECT_NEAR(table.reflectance(albedo), reflectance, 0.01f) << reflectance;
        EXPECT_NEAR(table.reflectance(table.singleScatteringAlbedo(reflectance)), reflectance, 0.003f) << reflectance;
    }
    // Nothing absorbs: all light comes out again, but for the walks cut off at 16384 scatterings
    // (about 1%: the chance of a walk lasting n steps in a half-space falls as n^-1/2).
    EXPECT_NEAR(table.reflectance(1), 1, 0.015f);
    EXPECT_EQ(table.singleScatteringAlbedo(0), 0);
    // Chiang et al.'s fit at its ends: black gives 0, white gives 1.
    EXPECT_NEAR(chiangSingleScatteringAlbedo(0), 0, 1e-5);
    EXPECT_NEAR(chiangSingleScatteringAlbedo(1), 1, 1e-5);
}

TEST(Subsurface, BoundaryTrapsLightSoTheSameReflectanceNeedsAHigherAlbedo) {
    const SubsurfaceAlbedoTable matched(1.0f), skin(1.33f);
    for (float reflectance : {0.2f, 0.5f, 0.8f}) {
        EXPECT_GT(skin.singleScatteringAlbedo(reflectance), matched.singleScatteringAlbedo(reflectance)) << reflectance;
        EXPECT_NEAR(skin.reflectance(skin.singleScatteringAlbedo(reflectance)), reflectance, 0.003f) << reflectance;
    }
}

// A sphere of non-absorbing subsurface material with an index-matched smooth boundary, under a
// uniform sky of 1, looks exactly like the sky.
TEST(Subsurface, NonAbsorbingVolumeInAFurnaceStaysAtOne) {
    test::TempDir dir;
    const std::string world = std::string(test::kWhiteSky) +
                              "Material \"subsurface\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [2 5 10] \"float g\" 0.4"
                              " \"float eta\" 1\nShape \"sphere\" \"float radius\" 1\n";
    const test::RadianceProbe probe(test::probeScene(dir, world), IntegratorType::VolPath, 5);
    test::expectRelative(meanOverDisk(probe, 100000), {1, 1, 1}, 0.01, "furnace");
}

// Rendered round trip of "reflectance" + "mfp": a sphere 100 mean free paths across (near enough
// to a semi-infinite medium) under a uniform sky reflects what was asked, plus for eta 1.33 the
// boundary's own reflection: F + (1 - F) R with F the boundary's diffuse Fresnel reflectance.
TEST(Subsurface, RenderedSphereReflectsTheRequestedReflectance) {
    const Vec3f requested{0.2f, 0.5f, 0.8f};
    for (float eta : {1.0f, 1.33f}) {
        test::TempDir dir;
        const std::string world = std::string(test::kWhiteSky) + "Material \"subsurface\" \"rgb reflectance\" [0.2 0.5 0.8]"
                                  " \"rgb mfp\" [0.01 0.01 0.01] \"float eta\" " + std::to_string(eta) +
                                  "\nShape \"sphere\" \"float radius\" 1\n";
        const test::RadianceProbe probe(test::probeScene(dir, world), IntegratorType::VolPath, 5);
        const float f = diffuseFresnel(eta);
        const Vec3f expected = Vec3f{f, f, f} + (1 - f) * requested;
        test::expectRelative(meanOverDisk(probe, 20000), expected, 0.03, "eta " + std::to_string(eta));
    }
}

// An absorbing slab 0 < z < d behind smooth boundaries of index 1.5, looked through along its
// normal at a black-backed light of radiance 1: the light passes both faces (T = 1 - R each) and
// every even number of internal reflections (R^2 each, another pass both ways):
//   T^2 exp(-sigma_t d) / (1 - R^2 exp(-2 sigma_t d)),  R = ((1.5 - 1) / (1.5 + 1))^2.
TEST(Subsurface, SlabTransmittanceIsBeerLambertTimesFresnel) {
    const float d = 0.3f, r = 0.04f, t = 1 - r;
    const Vec3f sigma{0.5f, 1, 2};
    Vec3f expected;
    for (int c = 0; c < 3; ++c) {
        const float once = std::exp(-sigma[c] * d);
        expected = expected + Vec3f{c == 0 ? 1.0f : 0, c == 1 ? 1.0f : 0, c == 2 ? 1.0f : 0} * (t * t * once / (1 - r * r * once * once));
    }
    test::TempDir dir;
    const std::string world =
        "AttributeBegin Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n"
        "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
        "Translate 0 0 2 Shape \"disk\" \"float radius\" 1000 AttributeEnd\n"
        "Material \"subsurface\" \"rgb sigma_a\" [0.5 1 2] \"rgb sigma_s\" [0 0 0] \"float eta\" 1.5\n"
        "AttributeBegin ReverseOrientation Shape \"disk\" \"float radius\" 1000 AttributeEnd\n"
        "Shape \"disk\" \"float height\" " + std::to_string(d) + " \"float radius\" 1000\n";
    const test::RadianceProbe probe(test::probeScene(dir, world), IntegratorType::VolPath, 5);
    Vec3f sum;
    const int n = 20000;
    for (int i = 0; i < n; ++i) sum += probe.once({0, 0, -1}, {0, 0, 1}, std::uint64_t(i));
    test::expectRelative(sum / float(n), expected, 0.01, "slab");
}

const Material& onlyMaterial(const SceneDescription& s) { return *s.shapes.at(0).material; }

TEST(Subsurface, ReadsPbrt4sParameterForms) {
    test::TempDir dir;
    const auto parse = [&](const std::string& params, const std::string& options = "") {
        return parseSceneFile(test::probeScene(dir, "Material \"subsurface\" " + params + "\nShape \"sphere\"\n", options));
    };
    const SurfaceHit hit{};
    // A measured medium by name, per mm, times scale (the sssdragon scene's form).
    const SceneDescription named = parse("\"string name\" \"Skin1\" \"float scale\" 10");
    const InteriorMedium skin = onlyMaterial(named).interiorAt(hit);
    EXPECT_NEAR(skin.sigmaA.x, 0.32f, 1e-5);
    EXPECT_NEAR(skin.sigmaS.z, 10.1f, 1e-4);
    // The default: pbrt's coefficients (whole milk's), g 0.
    const InteriorMedium milk = onlyMaterial(parse("")).interiorAt(hit);
    EXPECT_NEAR(milk.sigmaS.y, 3.21f, 1e-5);
    EXPECT_NEAR(milk.sigmaA.z, 0.014f, 1e-6);
    // reflectance and mfp: sigma_t = 1 / (scale mfp), the albedo from the table.
    const InteriorMedium fromColour = onlyMaterial(parse("\"rgb reflectance\" [0.5 0.5 0.5] \"rgb mfp\" [1 2 4] \"float scale\" 0.5 "
                                                         "\"float eta\" 1")).interiorAt(hit);
    EXPECT_NEAR(fromColour.sigmaA.x + fromColour.sigmaS.x, 2, 1e-4);
    EXPECT_NEAR(fromColour.sigmaA.z + fromColour.sigmaS.z, 0.5, 1e-4);
    EXPECT_NEAR(fromColour.sigmaS.x / 2, chiangSingleScatteringAlbedo(0.5f), 0.01);
    // The path integrator becomes volpath, with a note naming the material.
    const SceneDescription path = parse("", "Integrator \"path\"\n");
    EXPECT_EQ(path.integrator.type, IntegratorType::VolPath);
    ASSERT_FALSE(path.warnings.empty());
    EXPECT_NE(path.warnings.back().find("subsurface material at"), std::string::npos) << path.warnings.back();
}

TEST(Subsurface, RefusesBadParametersNamingTheLine) {
    test::TempDir dir;
    const auto error = [&](const std::string& world) {
        return test::sceneErrorOf(test::probeScene(dir, world + "\nShape \"sphere\"\n"));
    };
    const auto expectError = [&](const std::string& world, const std::string& expected) {
        const std::string e = error(world);
        // The header's three lines and WorldBegin come first; the material is the world's last line.
        const std::string line = "s.pbrt:" + std::to_string(5 + std::count(world.begin(), world.end(), '\n'));
        EXPECT_NE(e.find(line), std::string::npos) << e;
        EXPECT_NE(e.find(expected), std::string::npos) << e;
    };
    expectError("Material \"subsurface\" \"string name\" \"Marmite\"", "no measured medium is named \"Marmite\"");
    expectError("Material \"subsurface\" \"rgb sigma_a\" [1 1 1]", "give both \"sigma_a\" and \"sigma_s\"");
    expectError("Material \"subsurface\" \"rgb sigma_a\" [1 -1 1] \"rgb sigma_s\" [1 1 1]", "sigma_a must not be negative");
    expectError("Material \"subsurface\" \"float g\" 1", "g must lie in (-1, 1)");
    expectError("Material \"subsurface\" \"float scale\" -2", "scale must not be negative");
    expectError("Material \"subsurface\" \"float eta\" 0", "must be positive");
    expectError("MakeNamedMaterial \"a\" \"string type\" \"subsurface\" MakeNamedMaterial \"b\" \"string type\" \"diffuse\"\n"
                "Material \"mix\" \"string materials\" [\"a\" \"b\"]",
                "a subsurface material cannot be mixed");
}

}  // namespace
}  // namespace lenslab
