// loopsubdiv: Loop's rules with pbrt-v3's boundary rules, every vertex pushed to its limit
// position, normals from the limit tangents; the refined meshes converge to one smooth surface.
#include <gtest/gtest.h>

#include <algorithm>

#include "shapes/LoopSubdivision.h"
#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

// A regular tetrahedron about the origin, faces wound counter-clockwise seen from outside.
const std::vector<Vec3f> kTetra = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
const std::vector<std::uint32_t> kTetraFaces = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};

// The icosahedron of unit circumradius.
std::vector<Vec3f> icosahedron() {
    const float t = (1 + std::sqrt(5.0f)) / 2;
    std::vector<Vec3f> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3f& x : p) x = normalize(x);
    return p;
}
const std::vector<std::uint32_t> kIcoFaces = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                                              11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                                              3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};

TEST(LoopSubdivision, TetrahedronLimitPointsHaveTheClosedForm) {
    // Valence 3: beta 3/16, gamma 1/5, so the limit of a corner is 2/5 of it plus 1/5 of each
    // neighbour, which sum to minus the corner: 1/5 of the corner. Refining never moves it.
    for (int levels : {0, 1, 3}) {
        const MeshData m = loopSubdivide(kTetra, kTetraFaces, levels);
        EXPECT_EQ(m.indices.size(), kTetraFaces.size() << (2 * levels));
        for (std::size_t v = 0; v < 4; ++v) {
            EXPECT_NEAR(m.p[v].x, 0.2f * kTetra[v].x, 1e-6) << levels;
            EXPECT_NEAR(m.p[v].y, 0.2f * kTetra[v].y, 1e-6) << levels;
            EXPECT_NEAR(m.p[v].z, 0.2f * kTetra[v].z, 1e-6) << levels;
            // pbrt-v3's limit normals point against the counter-clockwise winding: inward here.
            EXPECT_LT(dot(normalize(m.n[v]), normalize(kTetra[v])), -0.999f) << levels;
        }
    }
}

TEST(LoopSubdivision, IcosahedronConvergesToASmoothSurface) {
    const std::vector<Vec3f> ico = icosahedron();
    std::vector<float> spread;
    for (int levels : {1, 2, 3, 4}) {
        const MeshData m = loopSubdivide(ico, kIcoFaces, levels);
        float lo = 1e9f, hi = 0;
        for (std::size_t v = 0; v < m.p.size(); ++v) {
            const float r = length(m.p[v]);
            lo = std::min(lo, r);
            hi = std::max(hi, r);
            EXPECT_LT(dot(normalize(m.n[v]), m.p[v] / r), -0.995f);  // smooth: normals along the radius
        }
        // The original corners' limit points do not depend on the level: all lie on one limit surface.
        EXPECT_NEAR(length(m.p[0]), length(loopSubdivide(ico, kIcoFaces, 0).p[0]), 1e-6);
        EXPECT_LT(hi - lo, 0.03f * hi) << levels;  // nearly round
        spread.push_back(hi - lo);
    }
    // Sampled ever finer, the band of distances from the centre settles to the limit surface's.
    EXPECT_LT(std::fabs(spread[3] - spread[2]), 0.3f * std::fabs(spread[2] - spread[1]));
}

TEST(LoopSubdivision, BoundaryFollowsPbrtsBoundaryRules) {
    // One triangle: every vertex and edge lies on the boundary. Even boundary vertices move to
    // 3/4 of themselves plus 1/8 of each boundary neighbour, new ones sit at edge midpoints, and
    // pbrt-v3's boundary limit is 3/5 of the vertex plus 1/5 of each neighbour.
    const std::vector<Vec3f> tri = {{0, 0, 0}, {6, 0, 0}, {0, 6, 0}};
    const MeshData m0 = loopSubdivide(tri, {0, 1, 2}, 0);
    EXPECT_NEAR(m0.p[0].x, 1.2f, 1e-6);
    EXPECT_NEAR(m0.p[0].y, 1.2f, 1e-6);
    const MeshData m = loopSubdivide(tri, {0, 1, 2}, 1);
    ASSERT_EQ(m.p.size(), 6u);
    ASSERT_EQ(m.indices.size(), 12u);
    const Vec3f e0 = 0.75f * tri[0] + 0.125f * (tri[1] + tri[2]), e1 = 0.75f * tri[1] + 0.125f * (tri[0] + tri[2]);
    const Vec3f corner = 0.6f * e0 + 0.2f * (Vec3f{3, 0, 0} + Vec3f{0, 3, 0});
    EXPECT_NEAR(length(m.p[0] - corner), 0, 1e-5);
    const Vec3f edge = 0.6f * Vec3f{3, 0, 0} + 0.2f * (e0 + e1);  // the new vertex on edge (0, 1)
    EXPECT_NEAR(length(m.p[3] - edge), 0, 1e-5);
    for (const Vec3f& p : m.p) EXPECT_NEAR(p.z, 0, 1e-6);  // a flat patch stays flat
}

TEST(LoopSubdivision, SceneShapeAndErrors) {
    test::TempDir dir;
    const SceneDescription s = test::parseWorld(dir,
        "Shape \"loopsubdiv\" \"integer nlevels\" 2 \"point P\" [1 1 1  1 -1 -1  -1 1 -1  -1 -1 1] "
        "\"integer indices\" [0 1 2  0 2 3  0 3 1  1 3 2]");
    EXPECT_EQ(s.shapes.at(0).shape->primitiveCount(), 4u * 16);
    try {
        test::parseWorld(dir, "Shape \"loopsubdiv\" \"point P\" [0 0 0  1 0 0  0 1 0  0 0 1  1 1 1] "
                              "\"integer indices\" [0 1 2  0 1 3  0 1 4]");
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("s.pbrt:5: Shape \"loopsubdiv\": the control mesh is not a manifold"),
                  std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
