// The transform directives against closed forms: Rotate turns points by the right-hand rule about
// its axis (Rodrigues' formula, as pbrt-v3): 90 degrees about z takes +y to -x, 120 degrees about
// (1, 1, 1) cycles the axes x -> y -> z. A Scale with a zero factor, in any axis, is an error (its
// transform has no inverse for normals and rays).
#include <gtest/gtest.h>

#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

// Where Rotate `rotation` puts the points (1, 0, 0), (0, 1, 0) and (0, 0, 1): the vertices of a triangle.
std::vector<Vec3f> rotatedAxes(const std::string& rotation) {
    test::TempDir dir;
    const SceneDescription s = test::parseWorld(dir, "Rotate " + rotation + "\nShape \"trianglemesh\" "
                                                     "\"integer indices\" [0 1 2] \"point P\" [1 0 0  0 1 0  0 0 1]");
    std::vector<Vec3f> points;
    for (const auto& [b1, b2] : {std::pair{0.0f, 0.0f}, std::pair{1.0f, 0.0f}, std::pair{0.0f, 1.0f}}) {
        SurfaceHit h;
        s.shapes.at(0).shape->surface({}, {}, 0, 0, b1, b2, h);
        points.push_back(h.p);
    }
    return points;
}

void expectPoint(Vec3f p, Vec3f want) {
    EXPECT_NEAR(p.x, want.x, 1e-6);
    EXPECT_NEAR(p.y, want.y, 1e-6);
    EXPECT_NEAR(p.z, want.z, 1e-6);
}

TEST(RotateDirective, TurnsByTheRightHandRuleAboutItsAxis) {
    const std::vector<Vec3f> quarter = rotatedAxes("90 0 0 1");
    expectPoint(quarter[0], {0, 1, 0});
    expectPoint(quarter[1], {-1, 0, 0});
    expectPoint(quarter[2], {0, 0, 1});
    const std::vector<Vec3f> cycle = rotatedAxes("120 1 1 1");
    expectPoint(cycle[0], {0, 1, 0});
    expectPoint(cycle[1], {0, 0, 1});
    expectPoint(cycle[2], {1, 0, 0});
}

TEST(ScaleDirective, AZeroFactorInAnyAxisIsAnError) {
    test::TempDir dir;
    for (const char* factors : {"0 1 1", "1 0 1", "1 1 0"}) {
        const std::string e = test::sceneErrorOf(test::shapeScene(dir, std::string("Scale ") + factors));
        EXPECT_NE(e.find("s.pbrt:5: Scale"), std::string::npos) << e;
        EXPECT_NE(e.find("zero scale factor"), std::string::npos) << e;
    }
}

}  // namespace
}  // namespace lenslab
