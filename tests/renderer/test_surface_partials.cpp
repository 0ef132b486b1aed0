// dp/du and dp/dv at hits, as pbrt-v3 defines them: each quadric's against its own (u, v) (a small
// step along dp/du, put back on the surface, must land at u + step), and triangles' from their
// corners' (u, v), pbrt-v3's default (u, v) and its fallback frame. dn/du and dn/dv: each quadric's
// against central differences of its unit normal over the same steps, the sphere's closed form
// dp/du / r, and triangles' from their vertex normals, as pbrt-v3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

using test::trace;

// The hit seen from `above` the surface point p along its normal n.
Intersection hitFromAbove(const SceneGeometry& g, Vec3f p, Vec3f n) {
    Intersection it;
    EXPECT_TRUE(trace(g, p + 0.05f * n, -n, it));
    return it;
}

// Steps of `eps` along dp/du and dp/dv from points drawn on the shape, projected back onto it along
// the normal, change (u, v) by (eps, 0) and (0, eps) up to the surface's curvature (eps^2). Also
// dp/du x dp/dv runs along the normal (against it when `reversed`), and dn/du and dn/dv are the central differences of
// the oriented unit normal over steps of +-eps (the eps^2 drift cancels between the two sides).
void expectPartialsMatchUv(const std::string& world, bool reversed = false) {
    test::TempDir dir;
    SceneDescription scene = test::parseWorld(dir, world);
    const std::shared_ptr<const Shape> shape = scene.shapes.at(0).shape;  // the geometry takes the scene's shapes
    const SceneGeometry g(scene);
    constexpr float kEps = 1e-3f;
    for (float u1 : {0.3f, 0.55f, 0.8f})
        for (float u2 : {0.2f, 0.45f, 0.7f}) {
            const ShapeSample s = shape->samplePrimitive(0, u1, u2);
            const SurfaceHit h = hitFromAbove(g, s.p, s.n).hit;
            const std::string where = world + " at (" + std::to_string(h.u) + ", " + std::to_string(h.v) + ")";
            EXPECT_GT((reversed ? -1 : 1) * dot(normalize(cross(h.dpdu, h.dpdv)), h.ng), 0.999f) << where;
            const SurfaceHit alongU = hitFromAbove(g, h.p + kEps * h.dpdu, h.ng).hit;
            EXPECT_NEAR(alongU.u - h.u, kEps, 0.03 * kEps) << where;
            EXPECT_NEAR(alongU.v - h.v, 0, 0.03 * kEps) << where;
            const SurfaceHit alongV = hitFromAbove(g, h.p + kEps * h.dpdv, h.ng).hit;
            EXPECT_NEAR(alongV.u - h.u, 0, 0.03 * kEps) << where;
            EXPECT_NEAR(alongV.v - h.v, kEps, 0.03 * kEps) << where;
            const std::tuple<Vec3f, Vec3f, const char*> steps[] = {{h.dpdu, h.dndu, "dn/du"},
                                                                   {h.dpdv, h.dndv, "dn/dv"}};
            for (const auto& [dp, dn, name] : steps) {
                const Vec3f ahead = hitFromAbove(g, h.p + kEps * dp, h.ng).hit.ng;
                const Vec3f behind = hitFromAbove(g, h.p - kEps * dp, h.ng).hit.ng;
                const Vec3f difference = (ahead - behind) / (2 * kEps);
                EXPECT_LT(length(dn - difference), 1e-3f * (1 + length(dn))) << where << " " << name;
            }
        }
}

TEST(SurfacePartials, QuadricsMatchTheirOwnUv) {
    expectPartialsMatchUv("Shape \"sphere\" \"float radius\" 2");
    expectPartialsMatchUv("Shape \"sphere\" \"float radius\" 1 \"float zmin\" -0.5 \"float zmax\" 0.8 \"float phimax\" 270");
    expectPartialsMatchUv("Shape \"disk\" \"float radius\" 2 \"float innerradius\" 0.5 \"float height\" 0.3");
    expectPartialsMatchUv("Shape \"cylinder\" \"float radius\" 1.5 \"float zmin\" -1 \"float zmax\" 2 \"float phimax\" 300");
    expectPartialsMatchUv("Shape \"cone\" \"float radius\" 1.5 \"float height\" 2");
    expectPartialsMatchUv("Shape \"paraboloid\" \"float radius\" 1 \"float zmin\" 0.2 \"float zmax\" 2");
    // pbrt-v3's hyperboloid dp/dv follows the segment p1-p2, exact when it is a ruling: x = 1, y = z
    // lies on x^2 + y^2 - z^2 = 1.
    expectPartialsMatchUv("Shape \"hyperboloid\" \"point p1\" [1 -1 -1] \"point p2\" [1 1 1]");
}

// The partials come out in world space through any transform, shear and mirror included.
TEST(SurfacePartials, QuadricsUnderTransforms) {
    expectPartialsMatchUv("Rotate 30 1 1 0\nScale 1 2 0.5\nShape \"sphere\"");
    expectPartialsMatchUv("Transform [1 0 0 0  0.4 1 0 0  0 0 1.5 0  0.2 0.1 0 1]\nShape \"cylinder\"");
    expectPartialsMatchUv("Scale -1 1 1\nShape \"cone\" \"float radius\" 1 \"float height\" 1.5");
    // The normal's partials too, through non-uniform scales (where pbrt-v3's inverse transpose alone
    // would be off) and ReverseOrientation.
    expectPartialsMatchUv("Scale 0.7 1.3 1\nShape \"disk\" \"float radius\" 2 \"float innerradius\" 0.5");
    expectPartialsMatchUv("Rotate 40 0 1 1\nScale 2 1 0.6\nShape \"cylinder\" \"float phimax\" 300");
    expectPartialsMatchUv("Scale 1.4 0.8 1.1\nShape \"cone\" \"float radius\" 1.5 \"float height\" 2");
    expectPartialsMatchUv("Rotate 20 1 0 0\nScale 1 1.5 0.7\n"
                          "Shape \"paraboloid\" \"float radius\" 1 \"float zmin\" 0.2 \"float zmax\" 2");
    expectPartialsMatchUv("Scale 0.8 1.2 1.5\nShape \"hyperboloid\" \"point p1\" [1 -1 -1] \"point p2\" [1 1 1]");
    expectPartialsMatchUv("Scale 1 2 0.5\nReverseOrientation\nShape \"sphere\" \"float zmin\" -0.5 \"float zmax\" 0.8",
                          true);
}

// A sphere of radius r has n = (p - centre) / r, so dn/du = dp/du / r and dn/dv = dp/dv / r: here a
// radius 2 scaled by 1.5, r = 3, also as an instance scaled by 1.5; ReverseOrientation turns n
// inward, and with it its partials.
TEST(SurfacePartials, SphereNormalTurnsAsDpOverRadius) {
    const std::string placed = "Translate 0.5 0 8\nRotate 30 1 1 0\nScale 1.5 1.5 1.5\n";
    const std::string sphere = "Shape \"sphere\" \"float radius\" 2\n";
    const std::pair<std::string, float> cases[] = {
        {placed + sphere, 1.0f},
        {placed + "ReverseOrientation\n" + sphere, -1.0f},
        {"ObjectBegin \"s\"\n" + sphere + "ObjectEnd\n" + placed + "ObjectInstance \"s\"", 1.0f}};
    for (const auto& [world, sign] : cases) {
        test::TempDir dir;
        const auto g = test::geometryOf(dir, world);
        for (Vec3f target : {Vec3f{0.5f, 0, 5}, Vec3f{1.8f, 1.2f, 6}, Vec3f{-1.5f, -0.9f, 6.5f}}) {
            Intersection it;
            ASSERT_TRUE(trace(*g, {0, 0, 0}, target, it));
            const SurfaceHit& h = it.hit;
            EXPECT_LT(length(h.dndu - (sign / 3) * h.dpdu), 1e-5f * length(h.dpdu)) << world;
            EXPECT_LT(length(h.dndv - (sign / 3) * h.dpdv), 1e-5f * length(h.dpdv)) << world;
        }
    }
}

// The camera's ray down the axis meets the sphere's two poles, the cone's apex and the paraboloid's
// vertex: the partials stay finite there, as dp/du and dp/dv do; the unit sphere's still dp/du, and
// the cone's normal, which never turns along its rulings, gives no rounding noise as dn/dv.
TEST(SurfacePartials, NormalPartialsStayFiniteAtPolesApexAndVertex) {
    for (const std::string world : {"Translate 0 0 5\nShape \"sphere\"",
                                    "Translate 0 0 5\nRotate 180 1 0 0\nShape \"sphere\"",
                                    "Translate 0 0 3\nRotate 180 1 0 0\nShape \"cone\" \"float height\" 1",
                                    "Translate 0 0 3\nShape \"paraboloid\""}) {
        test::TempDir dir;
        const auto g = test::geometryOf(dir, world);
        Intersection it;
        ASSERT_TRUE(trace(*g, {0, 0, 0}, {0, 0, 1}, it)) << world;
        const SurfaceHit& h = it.hit;
        EXPECT_TRUE(allFinite(h.dndu) && allFinite(h.dndv)) << world;
        if (world.find("sphere") != std::string::npos) {
            EXPECT_LT(length(h.dndu - h.dpdu), 1e-5f) << world;
            EXPECT_LT(length(h.dndv - h.dpdv), 1e-5f * length(h.dpdv)) << world;
        }
        if (world.find("cone") != std::string::npos) {
            EXPECT_LT(length(h.dndv), 1e-6f) << world;
        }
    }
}

// A triangle z = 2 ahead of the camera with corners (0,0) (2,0) (0,3) about the point (0.3, 0.4).
std::string triangle(const std::string& extra) {
    return "Translate 0.3 0.4 2\nShape \"trianglemesh\" \"integer indices\" [0 1 2] "
           "\"point P\" [-0.5 -0.5 0  1.5 -0.5 0  -0.5 2.5 0] " + extra;
}

SurfaceHit triangleHit(const std::string& extra) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir, triangle(extra));
    Intersection it;
    EXPECT_TRUE(trace(*g, {0, 0, 0}, {0.3f, 0.4f, 2}, it));
    return it.hit;
}

void expectVec(Vec3f got, Vec3f want, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, 1e-5) << what;
    EXPECT_NEAR(got.y, want.y, 1e-5) << what;
    EXPECT_NEAR(got.z, want.z, 1e-5) << what;
}

TEST(SurfacePartials, TrianglesFollowPbrt) {
    // (u, v) given: p = p0 + u (p1 - p0) + v (p2 - p0) here.
    SurfaceHit h = triangleHit("\"float uv\" [0 0  1 0  0 1]");
    expectVec(h.dpdu, {2, 0, 0}, "uv dpdu");
    expectVec(h.dpdv, {0, 3, 0}, "uv dpdv");
    // pbrt-v3's default (0,0) (1,0) (1,1): p = p0 + (u - v) (p1 - p0) + v (p2 - p0).
    h = triangleHit("");
    expectVec(h.dpdu, {2, 0, 0}, "default dpdu");
    expectVec(h.dpdv, {-2, 3, 0}, "default dpdv");
    // (u, v) spanning nothing: pbrt-v3's frame around the unit (p2 - p0) x (p1 - p0) = -z.
    h = triangleHit("\"float uv\" [0.5 0.5  0.5 0.5  0.5 0.5]");
    expectVec(h.dpdu, {0, -1, 0}, "degenerate dpdu");
    expectVec(h.dpdv, {-1, 0, 0}, "degenerate dpdv");
    // With shading normals: pbrt-v3's unit tangents around them, opposite to dp/du and dp/dv.
    h = triangleHit("\"float uv\" [0 0  1 0  0 1] \"normal N\" [0 0 1  0 0 1  0 0 1]");
    expectVec(h.dpdu, {-1, 0, 0}, "shading dpdu");
    expectVec(h.dpdv, {0, -1, 0}, "shading dpdv");
    expectVec(h.dndu, {0, 0, 0}, "equal normals dndu");
}

// The interpolated normal n0 + u (n1 - n0) + v (n2 - n0) of pbrt-v3's triangles changes by n1 - n0
// along u and n2 - n0 along v here; zero without normals; and with (u, v) spanning nothing, pbrt-v3's
// frame around (n2 - n0) x (n1 - n0) = (-0.12, -0.12, -0.36), not normalised.
TEST(SurfacePartials, TriangleNormalPartialsFollowPbrt) {
    const std::string normals = " \"normal N\" [0 0 1  0.6 0 0.8  0 0.6 0.8]";
    SurfaceHit h = triangleHit("\"float uv\" [0 0  1 0  0 1]" + normals);
    expectVec(h.dndu, {0.6f, 0, -0.2f}, "dndu");
    expectVec(h.dndv, {0, 0.6f, -0.2f}, "dndv");
    h = triangleHit("\"float uv\" [0 0  1 0  0 1]");
    expectVec(h.dndu, {0, 0, 0}, "flat dndu");
    expectVec(h.dndv, {0, 0, 0}, "flat dndv");
    h = triangleHit("\"float uv\" [0.5 0.5  0.5 0.5  0.5 0.5]" + normals);
    expectVec(h.dndu, {0, -0.9486833f, 0.3162278f}, "degenerate dndu");
    expectVec(h.dndv, {-0.3794733f, 0.0379473f, 0.1138420f}, "degenerate dndv");
}

}  // namespace
}  // namespace lenslab
