// pbrt-v3's quadrics: where rays hit them, their (u, v) and normals by pbrt-v3's formulas, their
// partial areas against closed forms, area sampling over exactly the partial surface, and what
// the camera sees of them.
#include <gtest/gtest.h>

#include <cmath>

#include "sampling/Sampling.h"
#include "ShapeTestScenes.h"
#include "core/Pi.h"

namespace lenslab {
namespace {

using test::trace;

// The single shape of a world block.
std::shared_ptr<const Shape> shapeOf(const test::TempDir& dir, const std::string& world) {
    SceneDescription s = test::parseWorld(dir, world);
    EXPECT_EQ(s.shapes.size(), 1u);
    return s.shapes.at(0).shape;
}

// The surface record at a point drawn on a quadric (a ray one unit above it, straight down).
SurfaceHit surfaceAt(const Shape& shape, const ShapeSample& q) {
    SurfaceHit h;
    shape.surface(q.p + q.n, -q.n, 1, 0, 0, 0, h);
    return h;
}

TEST(Quadrics, SphereUvAndNormalsFollowPbrt) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir, "Shape \"sphere\" \"float radius\" 2");
    Intersection it;
    ASSERT_TRUE(trace(*g, {5, 0, 1}, {-1, 0, 0}, it));
    EXPECT_NEAR(it.hit.p.x, std::sqrt(3.0f), 1e-5);
    EXPECT_NEAR(it.hit.u, 0, 1e-6);
    EXPECT_NEAR(it.hit.v, 2.0 / 3, 1e-5);  // theta = 60 degrees: v = (theta - pi) / (0 - pi)
    EXPECT_NEAR(it.hit.ng.x, std::sqrt(3.0f) / 2, 1e-5);
    EXPECT_NEAR(it.hit.ng.z, 0.5, 1e-5);
    ASSERT_TRUE(trace(*g, {0, 5, 0}, {0, -1, 0}, it));
    EXPECT_NEAR(it.hit.u, 0.25, 1e-6);
    EXPECT_NEAR(it.hit.v, 0.5, 1e-6);
    ASSERT_TRUE(trace(*g, {0, 0, 0}, {0, -1, 0}, it));  // from inside: the far wall, normal still outward
    EXPECT_NEAR(it.t, 2, 1e-5);
    EXPECT_NEAR(it.hit.ng.y, -1, 1e-5);
    EXPECT_NEAR(it.hit.u, 0.75, 1e-6);
}

// pbrt-v3 flips a quadric's normal for ReverseOrientation and, separately, for a transform that
// swaps handedness; both flips cancel.
TEST(Quadrics, OrientationFollowsReverseOrientationAndMirrors) {
    test::TempDir dir;
    Intersection it;
    const auto normalX = [&](const std::string& world) {
        const auto g = test::geometryOf(dir, world);
        EXPECT_TRUE(trace(*g, {5, 0.1f, 0}, {-1, 0, 0}, it)) << world;
        return it.hit.ng.x;
    };
    for (const std::string cut : {"", " \"float phimax\" 300"}) {  // Embree's sphere batch, and the general quadric
        EXPECT_GT(normalX("Shape \"sphere\"" + cut), 0.99f) << cut;
        EXPECT_LT(normalX("ReverseOrientation\nShape \"sphere\"" + cut), -0.99f) << cut;
        EXPECT_LT(normalX("Scale -1 1 1\nShape \"sphere\"" + cut), -0.99f) << cut;
        EXPECT_GT(normalX("Scale -1 1 1\nReverseOrientation\nShape \"sphere\"" + cut), 0.99f) << cut;
    }
}

TEST(Quadrics, PartialSphereClipsAndShowsItsInside) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir, "Shape \"sphere\" \"float radius\" 1 \"float zmin\" -0.5 \"float zmax\" 0.75 "
                                         "\"float phimax\" 180");
    Intersection it;
    // Through the cut at y < 0 the ray meets the inside of the far half.
    ASSERT_TRUE(trace(*g, {0, -5, 0}, {0, 1, 0}, it));
    EXPECT_NEAR(it.hit.p.y, 1, 1e-5);
    EXPECT_NEAR(it.hit.ng.y, 1, 1e-5);
    EXPECT_NEAR(it.hit.u, 0.5, 1e-6);  // phi = 90 degrees of 180
    const double thetaMin = std::acos(-0.5), thetaMax = std::acos(0.75);
    EXPECT_NEAR(it.hit.v, (M_PI / 2 - thetaMin) / (thetaMax - thetaMin), 1e-5);
    EXPECT_FALSE(trace(*g, {0, 0, 5}, {0, 0, -1}, it) && it.hit.p.z > 0.76f);  // the cap above zmax is gone
    EXPECT_FALSE(trace(*g, {0.3f, -5, 0.9f}, {0, 1, 0}, it));                   // above zmax
}

TEST(Quadrics, CylinderDiskConeUvFollowPbrt) {
    test::TempDir dir;
    Intersection it;
    const auto cylinder = test::geometryOf(dir, "Shape \"cylinder\" \"float radius\" 0.5 \"float zmin\" -1 "
                                                "\"float zmax\" 3 \"float phimax\" 270");
    ASSERT_TRUE(trace(*cylinder, {0, 5, 2}, {0, -1, 0}, it));
    EXPECT_NEAR(it.hit.p.y, 0.5, 1e-5);
    EXPECT_NEAR(it.hit.u, 90.0 / 270, 1e-6);
    EXPECT_NEAR(it.hit.v, 0.75, 1e-6);
    EXPECT_NEAR(it.hit.ng.y, 1, 1e-6);
    ASSERT_TRUE(trace(*cylinder, {5, -0.3f, 0}, {-1, 0, 0}, it));  // phi in (270, 360) is cut: the far wall
    EXPECT_LT(it.hit.p.x, 0);

    const auto disk = test::geometryOf(dir, "Shape \"disk\" \"float height\" 0.5 \"float radius\" 2 "
                                            "\"float innerradius\" 1 \"float phimax\" 180");
    ASSERT_TRUE(trace(*disk, {-1.5f, 0.01f, 3}, {0, 0, -1}, it));
    EXPECT_NEAR(it.hit.p.z, 0.5, 1e-6);
    EXPECT_NEAR(it.hit.ng.z, 1, 1e-6);
    EXPECT_NEAR(it.hit.u, 1, 1e-2);   // phi just under 180 degrees
    EXPECT_NEAR(it.hit.v, 0.5, 1e-3); // (radius - rho) / (radius - innerradius)
    EXPECT_FALSE(trace(*disk, {0.5f, 0.5f, 3}, {0, 0, -1}, it));   // in the hole
    EXPECT_FALSE(trace(*disk, {1.5f, -0.1f, 3}, {0, 0, -1}, it));  // phi > 180

    const auto cone = test::geometryOf(dir, "Shape \"cone\" \"float height\" 2 \"float radius\" 1");
    ASSERT_TRUE(trace(*cone, {5, 0, 1}, {-1, 0, 0}, it));
    EXPECT_NEAR(it.hit.p.x, 0.5, 1e-5);
    EXPECT_NEAR(it.hit.v, 0.5, 1e-6);
    EXPECT_NEAR(it.hit.ng.x, 2 / std::sqrt(5.0f), 1e-5);  // along (height, 0, radius)
    EXPECT_NEAR(it.hit.ng.z, 1 / std::sqrt(5.0f), 1e-5);
}

TEST(Quadrics, ParaboloidAndHyperboloidHitsLieOnTheirSurfaces) {
    test::TempDir dir;
    const auto para = test::geometryOf(dir, "Shape \"paraboloid\" \"float radius\" 2 \"float zmin\" 0.5 \"float zmax\" 3");
    const auto hyper = test::geometryOf(dir, "Shape \"hyperboloid\" \"point p1\" [1 -1 -1] \"point p2\" [1 1 1]");
    Intersection it;
    for (float x : {-1.3f, -0.7f, 0.4f, 1.1f}) {
        ASSERT_TRUE(trace(*para, {x, 5, 1.7f}, {0, -1, 0.1f}, it)) << x;
        const Vec3f p = it.hit.p;
        EXPECT_NEAR(p.z, 3 * (p.x * p.x + p.y * p.y) / 4, 1e-4) << x;  // z = zmax rho^2 / radius^2
        EXPECT_NEAR(it.hit.v, (p.z - 0.5) / 2.5, 1e-4);
        // The line x = 1, y = z is a ruling of x^2 + y^2 - z^2 = 1, which pbrt-v3's fit recovers.
        ASSERT_TRUE(trace(*hyper, {x, -5, 0.3f * x}, {-0.05f * x, 1, 0}, it)) << x;
        const Vec3f h = it.hit.p;
        EXPECT_NEAR(h.x * h.x + h.y * h.y - h.z * h.z, 1, 1e-4) << x;
        const Vec3f expectedNormal = normalize(Vec3f{h.x, h.y, -h.z});
        EXPECT_GT(dot(it.hit.ng, expectedNormal), 0.9999f);
    }
    ASSERT_TRUE(trace(*hyper, {0, 5, 0}, {0, -1, 0}, it));
    EXPECT_NEAR(it.hit.u, 0.25, 1e-5);  // phi measured from the ruling's point (1, 0, 0)
    EXPECT_NEAR(it.hit.v, 0.5, 1e-5);
}

TEST(Quadrics, NonUniformScaleKeepsTheSurfaceExact) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir, "Scale 2 1 1\nShape \"sphere\"");
    Intersection it;
    ASSERT_TRUE(trace(*g, {1.9f, 0, -5}, {0, 0, 1}, it));
    EXPECT_NEAR(it.hit.p.z, -std::sqrt(1 - 0.95f * 0.95f), 1e-5);  // x^2 / 4 + z^2 = 1
    const Vec3f n = normalize(Vec3f{it.hit.p.x / 4, 0, it.hit.p.z});  // the ellipsoid's gradient
    EXPECT_GT(dot(it.hit.ng, n), 0.99999f);
    // A prolate spheroid, semi-axes 2, 1, 1: area 2 pi (1 + 2 asin(e) / e), e = sqrt(3) / 2.
    SceneDescription s = test::parseWorld(dir, "Scale 2 1 1\nShape \"sphere\"");
    const double e = std::sqrt(3.0) / 2;
    EXPECT_NEAR(s.shapes[0].shape->primitiveArea(0), 2 * M_PI * (1 + 2 * std::asin(e) / e), 1e-3);
}

TEST(Quadrics, PartialAreasMatchClosedForms) {
    test::TempDir dir;
    const auto area = [&](const std::string& world) { return shapeOf(dir, world)->primitiveArea(0); };
    EXPECT_NEAR(area("Shape \"sphere\" \"float zmin\" -0.5 \"float phimax\" 180"), M_PI * 1.5, 1e-5);
    EXPECT_NEAR(area("Scale 3 3 3 Shape \"sphere\" \"float zmin\" -0.5 \"float phimax\" 180"), 9 * M_PI * 1.5, 1e-4);
    EXPECT_NEAR(area("Shape \"cylinder\" \"float radius\" 0.5 \"float zmin\" 0 \"float zmax\" 2 \"float phimax\" 90"),
                0.5 * M_PI, 1e-5);
    EXPECT_NEAR(area("Shape \"disk\" \"float innerradius\" 0.5 \"float phimax\" 90"), M_PI / 4 * 0.75, 1e-6);
    EXPECT_NEAR(area("Shape \"cone\" \"float height\" 2 \"float phimax\" 270"), 0.5 * std::sqrt(5.0) * 1.5 * M_PI, 1e-5);
    // Paraboloid z = rho^2 from z = 0.25 to 1: pi / 6 ((1 + 4 z)^(3/2)) between the limits.
    EXPECT_NEAR(area("Shape \"paraboloid\" \"float zmin\" 0.25"), M_PI / 6 * (std::pow(5.0, 1.5) - std::pow(2.0, 1.5)), 1e-5);
    // x^2 + y^2 = 1 + z^2 for |z| <= 1: 2 pi times the integral of sqrt(1 + 2 z^2).
    EXPECT_NEAR(area("Shape \"hyperboloid\" \"point p1\" [1 -1 -1] \"point p2\" [1 1 1]"),
                2 * M_PI * (std::sqrt(3.0) + std::asinh(std::sqrt(2.0)) / std::sqrt(2.0)), 1e-4);
}

// Points drawn on each partial quadric lie on the surface a ray sees, inside its (u, v) square, with
// the density the light reports; the lower half in v (a closed form per shape) gets its share.
TEST(Quadrics, AreaSamplingCoversExactlyThePartialSurface) {
    test::TempDir dir;
    const double thetaMin = std::acos(-0.5), thetaMax = std::acos(0.8), thetaHalf = 0.5 * (thetaMin + thetaMax);
    struct Case {
        std::string world;
        double lowerHalfShare;  // of the area, where v < 1/2
    };
    const Case cases[] = {
        {"Shape \"sphere\" \"float zmin\" -0.5 \"float zmax\" 0.8 \"float phimax\" 200",
         (std::cos(thetaHalf) + 0.5) / 1.3},
        {"Shape \"cylinder\" \"float zmin\" 0 \"float zmax\" 2 \"float phimax\" 100", 0.5},
        {"Shape \"disk\" \"float innerradius\" 0.5 \"float phimax\" 300", (1 - 0.75 * 0.75) / (1 - 0.25)},
        {"Shape \"cone\" \"float phimax\" 120", 0.75},
        {"Shape \"paraboloid\" \"float zmin\" 0.2 \"float phimax\" 250",
         (std::pow(1 + 4 * 0.6, 1.5) - std::pow(1.8, 1.5)) / (std::pow(5.0, 1.5) - std::pow(1.8, 1.5))},
        {"Shape \"hyperboloid\" \"point p1\" [1 -1 -1] \"point p2\" [1 1 1] \"float phimax\" 90", 0.5},
        {"Scale 1 2 0.5\nShape \"cylinder\" \"float phimax\" 180", 0.5},
    };
    for (const Case& c : cases) {
        const auto shape = shapeOf(dir, c.world);
        Pcg32 rng(7);
        constexpr int kN = 4000;
        double lower = 0, total = 0;
        for (int i = 0; i < kN; ++i) {
            const ShapeSample q = shape->samplePrimitive(0, rng.uniform(), rng.uniform());
            const SurfaceHit h = surfaceAt(*shape, q);
            ASSERT_NEAR(length(h.p - q.p), 0, 1e-4) << c.world;
            ASSERT_GT(dot(h.ng, q.n), 0.999f) << c.world;
            ASSERT_TRUE(h.u >= -1e-5f && h.u <= 1 + 1e-5f && h.v >= -1e-5f && h.v <= 1 + 1e-5f) << c.world << " " << h.u << " " << h.v;
            ASSERT_NEAR(shape->primitivePdf(0, h) / q.pdf, 1, 1e-3) << c.world;
            total += 1 / q.pdf;
            if (h.v < 0.5f) lower += 1 / q.pdf;
        }
        EXPECT_NEAR(total / kN / shape->primitiveArea(0), 1, 0.02) << c.world;
        EXPECT_NEAR(lower / total, c.lowerHalfShare, 0.025) << c.world;
    }
}

TEST(QuadricErrors, DegenerateParametersAreNamed) {
    test::TempDir dir;
    const auto error = [&](const std::string& world) {
        try {
            test::parseWorld(dir, world);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(error("Shape \"sphere\" \"float radius\" -1").find("radius must be positive"), std::string::npos);
    EXPECT_NE(error("Shape \"disk\" \"float innerradius\" 2").find("innerradius"), std::string::npos);
    // pbrt-v3's default hyperboloid, p1 (0 0 0) to p2 (1 1 1), is a cone through the axis: pbrt-v3 hangs.
    const std::string e = error("Shape \"hyperboloid\"");
    EXPECT_NE(e.find("s.pbrt:5: Shape \"hyperboloid\": p1 and p2 describe no hyperboloid"), std::string::npos) << e;
}

// --- what the camera sees ---------------------------------------------------------------------

// An emitting disk of radius 1 facing the camera 5 units away covers pi (17.6 px)^2.
TEST(QuadricImages, DiskLightIsADiskOfTheRightRadius) {
    test::TempDir dir;
    const auto render = [&](const std::string& world) {
        return test::render(test::shapeScene(dir, world), 64, 64, 4).image;
    };
    const double r = test::pixelsPerUnitAt(5);
    const Image facing = render("AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                "Translate 0 0 5\nReverseOrientation\nShape \"disk\"\nAttributeEnd");
    EXPECT_NEAR(test::brightPixels(facing, 0.5f), M_PI * r * r, 0.03 * M_PI * r * r);
    EXPECT_NEAR(test::lum(facing, 32, 32), 1, 1e-4);
    // Without ReverseOrientation it faces +z, away from the camera: one-sided, it shows nothing.
    const Image away = render("AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                              "Translate 0 0 5\nShape \"disk\"\nAttributeEnd");
    EXPECT_EQ(test::brightPixels(away, 0.01f), 0);
}

TEST(QuadricImages, HalfSphereShowsHalfAndItsInsideThroughTheCut) {
    test::TempDir dir;
    const double r = test::pixelsPerUnitAt(5), half = 0.5 * M_PI * r * r;
    const auto render = [&](const std::string& sided, const std::string& rotate) {
        return test::render(test::shapeScene(dir, "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1] "
                                                  "\"bool twosided\" " + sided + "\nTranslate 0 0 5\n" + rotate +
                                                  "Shape \"sphere\" \"float phimax\" 180\nAttributeEnd"),
                            64, 64, 4).image;
    };
    // Seen along z, phi in [0, 180] is the upper half (y >= 0): the top rows.
    const Image front = render("false", "");
    EXPECT_NEAR(test::brightPixels(front, 0.5f, 0, 32), half, 0.04 * half);
    EXPECT_EQ(test::brightPixels(front, 0.01f, 33, 64), 0);
    // Turned so that the cut faces the camera, only the inside shows: the back hemisphere's inner
    // wall, lit only when the light is two-sided.
    const Image inside = render("true", "Rotate 90 1 0 0\n");
    EXPECT_NEAR(test::brightPixels(inside, 0.5f), 2 * half, 0.04 * half);
    EXPECT_EQ(test::brightPixels(render("false", "Rotate 90 1 0 0\n"), 0.01f), 0);
}

TEST(QuadricImages, CylinderSilhouetteWidth) {
    test::TempDir dir;
    const Image im = test::render(test::shapeScene(dir, "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1] "
                                                       "\"bool twosided\" true\nTranslate 0 0 5\nRotate 90 1 0 0\n"
                                                       "Shape \"cylinder\" \"float radius\" 0.5 \"float zmin\" -3 \"float zmax\" 3\n"
                                                       "AttributeEnd"),
                                  64, 64, 4).image;
    // The silhouette's half-angle is asin(r / d); its width on the film, 2 tan of that.
    const double width = 2 * std::tan(std::asin(0.1)) * 5 * test::pixelsPerUnitAt(5);
    for (int row : {5, 32, 58}) {
        int lit = 0;
        float sum = 0;
        for (int x = 0; x < 64; ++x) {
            lit += test::lum(im, x, row) > 0.5f;
            sum += test::lum(im, x, row);
        }
        // Partial pixels at the edges add up; each of the two edge pixels' 4 samples can be off by a
        // quarter (0.17 or 0.33 in total over seeds 0-9, with either camera sampler).
        EXPECT_NEAR(sum, width, 0.5) << row;
        EXPECT_NEAR(lit, width, 1.01) << row;
    }
}

}  // namespace
}  // namespace lenslab
