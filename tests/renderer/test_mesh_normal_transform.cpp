// A mesh's vertex normals go to world space by the inverse transpose of its transform: under
// Scale 1 4 1 the normal (0, 1, 1) becomes (0, 1/4, 1), normalised, not the vector image (0, 4, 1).
#include <gtest/gtest.h>

#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

TEST(MeshNormalTransform, VertexNormalsFollowTheInverseTransposeUnderANonUniformScale) {
    test::TempDir dir;
    const SceneDescription s = test::parseWorld(dir, "Scale 1 4 1\n"
                                                     "Shape \"trianglemesh\" \"integer indices\" [0 1 2]\n"
                                                     "  \"point P\" [0 0 2  1 0 2  0 1 1]\n"
                                                     "  \"normal N\" [0 1 1  0 1 1  0 1 1]");
    ASSERT_EQ(s.shapes.size(), 1u);
    SurfaceHit h;
    s.shapes[0].shape->surface({}, {}, 0, 0, 0.3f, 0.3f, h);
    const double norm = std::sqrt(1.0 / 16 + 1);
    EXPECT_NEAR(h.ns.x, 0, 1e-6);
    EXPECT_NEAR(h.ns.y, 0.25 / norm, 1e-6);
    EXPECT_NEAR(h.ns.z, 1 / norm, 1e-6);
}

}  // namespace
}  // namespace lenslab
