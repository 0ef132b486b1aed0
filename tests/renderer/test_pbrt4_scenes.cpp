// pbrt-v4 scene files against closed forms: dialect detection, light normalisations, film
// exposure and white balance, conductor and coated materials, bilinear patches, gzip.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>

#include "BsdfTesting.h"
#include "TestScenes.h"
#include "core/DaylightSpectrum.h"
#include "core/Spectrum.h"
#include "film/WhiteBalance.h"
#include "materials/Material.h"
#include "sampling/EqualAreaSphere.h"
#include "scene/SceneDescription.h"

namespace lenslab {
namespace {

// A flat diffuse floor (z = 0) seen straight down by an orthographic camera.
const char* kFloorHeader = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"orthographic\"\n"
                           "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                           "Integrator \"path\" \"integer maxdepth\" 1\nWorldBegin\n";
const char* kFloor = "Material \"diffuse\" \"rgb reflectance\" [ .5 .5 .5 ]\n"
                     "Shape \"bilinearmesh\" \"point3 P\" [ -10 -10 0  10 -10 0  -10 10 0  10 10 0 ]\n";

TEST(Pbrt4Scenes, DetectsTheDialectPerFile) {
    test::TempDir dir;
    const auto dialect = [&](const std::string& body) {
        return parseSceneFile(dir.write("s.pbrt", "Camera \"perspective\"\nWorldBegin\n" + body)).dialect;
    };
    EXPECT_EQ(dialect("Material \"diffuse\"\nShape \"sphere\"\n"), SceneDialect::PbrtV4);
    EXPECT_EQ(dialect("MakeNamedMaterial \"m\" \"string type\" [ \"conductor\" ]\n"), SceneDialect::PbrtV4);
    EXPECT_EQ(dialect("Attribute \"shape\" \"float radius\" 2\nShape \"sphere\"\n"), SceneDialect::PbrtV4);
    EXPECT_EQ(dialect("LightSource \"point\" \"float power\" 10\n"), SceneDialect::PbrtV4);
    EXPECT_EQ(dialect("Material \"matte\"\nLightSource \"point\" \"rgb I\" [1 1 1]\nShape \"sphere\"\n"), SceneDialect::PbrtV3);
}

TEST(Pbrt4Scenes, DistantIlluminanceLightsADiffuseFloorWithReflectanceTimesEOverPi) {
    test::TempDir dir;
    const std::string scene = dir.write("s.pbrt", std::string(kFloorHeader) +
        "LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0 0 0] \"float illuminance\" 3\n" + kFloor);
    const RenderOutput out = test::render(scene, 8, 8, 4);
    EXPECT_NEAR(test::meanLum(out.image), 0.5 * 3 / M_PI, 1e-3);
}

TEST(Pbrt4Scenes, PointLightPowerGivesIntensityPOver4Pi) {
    test::TempDir dir;
    const SceneDescription s = parseSceneFile(dir.write("s.pbrt",
        "WorldBegin\nLightSource \"point\" \"float power\" 100\nLightSource \"point\" \"blackbody I\" 3000 \"float power\" 100\n"));
    // A white point light emits its power; a blackbody's luminance is normalised to 1 first.
    EXPECT_NEAR(luminance(s.lights[0]->power()), 100, 1e-3);
    EXPECT_NEAR(luminance(s.lights[1]->power()), 100, 0.1);
}

TEST(Pbrt4Scenes, UniformSkyIlluminanceAndScale) {
    test::TempDir dir;
    const SceneDescription s = parseSceneFile(dir.write("s.pbrt",
        "WorldBegin\nLightSource \"infinite\" \"float illuminance\" 6.283185307\nLightSource \"infinite\" \"float scale\" 3\n"));
    EXPECT_NEAR(luminance(s.lights[0]->emitted(nullptr, {0, 0, 1})), 2, 1e-4);  // E = pi L
    EXPECT_NEAR(luminance(s.lights[1]->emitted(nullptr, {0, 0, 1})), 3, 1e-4);
}

TEST(Pbrt4Scenes, FilmScalesByIsoTimesShutterInterval) {
    test::TempDir dir;
    const SceneDescription s = parseSceneFile(dir.write("s.pbrt",
        "Camera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 0.25\n"
        "Film \"rgb\" \"float iso\" 800\nWorldBegin\n"));
    EXPECT_NEAR(s.film.scale, 2.0, 1e-9);
}

TEST(Pbrt4Scenes, WhiteBalanceTurnsTheBalancedDaylightNeutral) {
    const Rgb3x3 identity = whiteBalanceMatrix(6504);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(identity[i], i % 4 == 0 ? 1 : 0, 0.01) << i;
    double x, y;
    daylightChromaticity(4000, x, y);
    const Vec3f white = xyzToRgb(x / y, 1, (1 - x - y) / y);
    const Vec3f balanced = applyRgbMatrix(whiteBalanceMatrix(4000), white);
    EXPECT_NEAR(balanced.x / balanced.y, 1, 0.01);
    EXPECT_NEAR(balanced.z / balanced.y, 1, 0.01);
}

std::shared_ptr<const Material> materialOf(test::TempDir& dir, const std::string& material) {
    const SceneDescription s = parseSceneFile(dir.write("m.pbrt", "WorldBegin\n" + material + "\nShape \"sphere\"\n"));
    return s.shapes.at(0).material;
}

// Normal-incidence reflectance of a smooth material: the weight of its mirror sample.
Vec3f normalReflectance(const Material& m) {
    BsdfSample s;
    const SurfaceHit h = test::flatHit();
    EXPECT_TRUE(m.sample(h, {0, 0, 1}, 0.5f, 0.5f, 0.5f, s));
    return s.weight;
}

TEST(Pbrt4Scenes, CopperFromNamedSpectraReflectsItsPublishedF0) {
    test::TempDir dir;
    const auto cu = materialOf(dir, "Material \"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" \"metal-Cu-k\"");
    const Vec3f f0 = normalReflectance(*cu);
    // Copper's reflectance at normal incidence in linear sRGB (Hoffman, "Physics and Math of
    // Shading", 2015): 0.955, 0.638, 0.538.
    EXPECT_NEAR(f0.x, 0.955, 0.03);
    EXPECT_NEAR(f0.y, 0.638, 0.03);
    EXPECT_NEAR(f0.z, 0.538, 0.03);
    const auto mirror = materialOf(dir, "Material \"conductor\" \"rgb reflectance\" [ .9 .6 .3 ]");
    const Vec3f r = normalReflectance(*mirror);
    EXPECT_NEAR(r.x, 0.9, 1e-3);
    EXPECT_NEAR(r.z, 0.3, 1e-3);
}

TEST(Pbrt4Scenes, CoatedDiffuseOfWhiteBaseConservesEnergy) {
    // A white furnace: a sphere whose white coated base and coat together reflect all the light
    // of a uniform sky looks exactly as bright as the sky.
    test::TempDir dir;
    const std::string scene = dir.write("s.pbrt",
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 10\nFilm \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
        "Integrator \"path\" \"integer maxdepth\" 50\nWorldBegin\nLightSource \"infinite\"\n"
        "Material \"coateddiffuse\" \"rgb reflectance\" [1 1 1] \"float thickness\" 0 \"float roughness\" 0\nShape \"sphere\"\n");
    EXPECT_NEAR(test::meanLum(test::render(scene, 8, 8, 256).image), 1.0, 0.02);
}

TEST(Pbrt4Scenes, CoatedMaterialsReflectTheSameFromBehindTheShadingNormal) {
    // pbrt-v4's layered materials are two-sided. Seen from behind the shading normal (as where a
    // coarse mesh's interpolated normals lean away from the viewer), the coat must not act as glass
    // seen from inside, which past the critical angle (41.8 degrees for eta 1.5) reflects all.
    test::TempDir dir;
    const Vec3f wo = test::direction(80, 0);
    const Vec3f below{-wo.x, -wo.y, -wo.z};
    // A smooth coat over a white base without absorption conserves energy exactly: albedo 1.
    const auto smooth = test::parseMaterial(dir, "Material \"coateddiffuse\" \"rgb reflectance\" [1 1 1] "
                                                 "\"float thickness\" 0 \"float roughness\" 0");
    EXPECT_NEAR(test::sampledAlbedo(*smooth, below, 200000).mean.y, 1.0, 0.01);
    // A rough coat, and a coated conductor: the same value as the mirrored pair in front.
    const SurfaceHit h = test::flatHit();
    const Vec3f wi = test::direction(75, 180);
    for (const char* m : {"Material \"coateddiffuse\" \"rgb reflectance\" [.4 .2 .2] \"float roughness\" 0.1",
                          "Material \"coatedconductor\" \"float interface.roughness\" 0.1 \"float conductor.roughness\" 0.1"}) {
        const auto coated = test::parseMaterial(dir, m);
        const Vec3f front = coated->evaluate(h, wo, wi), back = coated->evaluate(h, below, Vec3f{-wi.x, -wi.y, -wi.z});
        EXPECT_GT(front.y, 0) << m;
        EXPECT_NEAR(back.y, front.y, 1e-5f * front.y) << m;
    }
}

TEST(Pbrt4Scenes, ReadsGzippedIncludesAndAttributeDefaults) {
    test::TempDir dir;
    const std::string path = dir.write("part.pbrt.gz", "");
    gzFile f = gzopen(path.c_str(), "wb");
    const std::string text = "Attribute \"shape\" \"float radius\" 3\nShape \"sphere\"\n";
    gzwrite(f, text.data(), unsigned(text.size()));
    gzclose(f);
    const SceneDescription s = parseSceneFile(dir.write("s.pbrt", "WorldBegin\nImport \"part.pbrt.gz\"\n"));
    ASSERT_EQ(s.shapes.size(), 1u);
    EXPECT_EQ(s.dialect, SceneDialect::PbrtV4);
}

TEST(Pbrt4Scenes, EqualAreaMapRoundTrips) {
    for (float u = 0.05f; u < 1; u += 0.1f)
        for (float v = 0.05f; v < 1; v += 0.1f) {
            const Vec3f d = equalAreaSquareToSphere(u, v);
            EXPECT_NEAR(length(d), 1, 1e-5);
            float u2, v2;
            equalAreaSphereToSquare(d, u2, v2);
            EXPECT_NEAR(u2, u, 1e-4);
            EXPECT_NEAR(v2, v, 1e-4);
        }
}

}  // namespace
}  // namespace lenslab
