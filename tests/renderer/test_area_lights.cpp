// Diffuse area lights on every shape: the irradiance they give a point, estimated by sampling the
// lights (area sampling turned into solid angle) and by sampling directions and hitting them,
// agrees between the two estimates and with closed forms; power is pi L area.
#include <gtest/gtest.h>

#include <cmath>

#include "sampling/Sampling.h"
#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

constexpr int kSamples = 40000;

// Irradiance at p (normal n) from every light of the scene, by light sampling (with shadow rays).
double irradianceFromLightSamples(const SceneGeometry& g, Vec3f p, Vec3f n) {
    Pcg32 rng(3);
    double e = 0;
    for (const auto& light : g.lights())
        for (int i = 0; i < kSamples; ++i) {
            LightSample s;
            if (!light->sample(p, rng.uniform(), rng.uniform(), s)) continue;
            const float cosP = dot(s.wi, n);
            if (cosP <= 0 || g.occluded(p, s.wi, s.distance * (1 - 1e-4f), 0)) continue;
            e += s.radiance.x * cosP / s.pdf;
        }
    return e / kSamples;
}

// The same by cosine-weighted directions that hit an emitter; also checks each hit light's pdf
// against the density its sample() would give there, for multiple importance sampling.
double irradianceFromHits(const SceneGeometry& g, Vec3f p, Vec3f n) {
    Pcg32 rng(5);
    const Frame frame(n);
    double e = 0;
    for (int i = 0; i < kSamples; ++i) {
        const Vec3f w = frame.toWorld(cosineHemisphere(rng.uniform(), rng.uniform()));
        Intersection it;
        if (!test::trace(g, p, w, it) || !it.light) continue;
        e += M_PI * it.light->emitted(&it.hit, w).x;
        EXPECT_GT(it.light->pdf(p, w, &it.hit), 0);
    }
    return e / kSamples;
}

struct AreaLightCase {
    std::string world;  // an emitter of radiance 1 placed for a point at the origin facing +z
    double closedForm;  // the irradiance there, or 0 where there is none to compare with
};

TEST(AreaLights, EveryShapeGivesTheIrradianceItShould) {
    test::TempDir dir;
    const std::string light = "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n";
    const AreaLightCase cases[] = {
        // A sphere of radius 0.5 at distance 2 on the axis: pi sin^2(alpha).
        {light + "Translate 0 0 2\nShape \"sphere\" \"float radius\" 0.5", M_PI * 0.0625},
        // A disk of radius 1 at height 2 facing down: pi r^2 / (r^2 + h^2).
        {light + "Translate 0 0 2\nReverseOrientation\nShape \"disk\"", M_PI / 5},
        // A unit square of two triangles 2 above: four corner rectangles of X = Y = a / h, each
        // giving X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2)) times L.
        {light + "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
                 "\"point P\" [-0.5 -0.5 2  -0.5 0.5 2  0.5 0.5 2  0.5 -0.5 2]",
         4 * (0.5 / std::sqrt(4.25)) * std::atan(0.5 / std::sqrt(4.25))},
        // Partial and stretched shapes: the two estimates must agree.
        {light + "Translate 0 0 2\nShape \"sphere\" \"float zmin\" -0.9 \"float zmax\" 0.3 \"float phimax\" 250", 0},
        {light + "Translate 0 0 2\nScale 2 0.5 0.7\nShape \"sphere\"", 0},
        {light + "Translate 0 0 2\nRotate -90 1 0 0\nShape \"cylinder\" \"float phimax\" 200", 0},
        {light + "Translate 0 0 1\nReverseOrientation\nShape \"cone\" \"float phimax\" 300", 0},
        {light + "Translate 0 0 1\nShape \"paraboloid\" \"float zmin\" 0.3", 0},
        {light + "Translate 0 0 2\nRotate 90 0 1 0\nShape \"hyperboloid\" \"point p1\" [1 -1 -1] \"point p2\" [1 1 1] "
                 "\"float phimax\" 270", 0},
        {light + "\"bool twosided\" true\nTranslate 0 0 2\nShape \"disk\" \"float innerradius\" 0.4 \"float phimax\" 100", 0},
    };
    for (const AreaLightCase& c : cases) {
        const auto g = test::geometryOf(dir, c.world);
        ASSERT_FALSE(g->lights().empty());
        const double byLight = irradianceFromLightSamples(*g, {0, 0, 0}, {0, 0, 1});
        const double byHits = irradianceFromHits(*g, {0, 0, 0}, {0, 0, 1});
        ASSERT_GT(byHits, 0.01) << c.world;
        EXPECT_NEAR(byLight / byHits, 1, 0.03) << c.world << "\nlight sampling " << byLight << ", hits " << byHits;
        if (c.closedForm > 0) {
            EXPECT_NEAR(byLight / c.closedForm, 1, 0.01) << c.world;
        }
    }
}

TEST(AreaLights, PowerIsPiLTimesTheArea) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir, "AreaLightSource \"diffuse\" \"rgb L\" [2 1 0.5]\n"
                                         "Shape \"sphere\" \"float radius\" 0.5 \"float zmax\" 0 \"float phimax\" 180\n"
                                         "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
                                         "Shape \"trianglemesh\" \"point P\" [0 0 0  2 0 0  0 3 0]\nAttributeEnd");
    ASSERT_EQ(g->lights().size(), 2u);
    EXPECT_NEAR(g->lights()[0]->power().x, 2 * M_PI * (M_PI * 0.5 * 0.5), 1e-4);  // a quarter sphere: pi r^2
    EXPECT_NEAR(g->lights()[0]->power().z, 0.5 * M_PI * (M_PI * 0.5 * 0.5), 1e-4);
    EXPECT_NEAR(g->lights()[1]->power().y, 2 * M_PI * 3, 1e-4);  // both sides of a triangle of area 3
}

}  // namespace
}  // namespace lenslab
