// Curves: Embree's curve primitives behind pbrt-v3's "curve" shape. A straight curve of width w seen
// through an orthographic window is a band w tall, whatever its type, basis and degree.
#include <gtest/gtest.h>

#include "scene/SceneDescription.h"
#include "ShapeTestScenes.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// Rows of the middle column darker than the sky (the curve is a grey diffuse band on a bright sky).
int bandRows(const std::string& curve) {
    test::TempDir dir;
    const std::string p = dir.write("c.pbrt", "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"orthographic\" \"float screenwindow\" [-1 1 -1 1]\n"
                                              "Film \"image\" \"integer xresolution\" 64 \"integer yresolution\" 64\n"
                                              "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                                              "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n" + curve + "\nWorldEnd\n");
    const RenderOutput out = test::render(p, 64, 64, 16);
    int rows = 0;
    for (int y = 0; y < 64; ++y) rows += test::lum(out.image, 32, y) < 0.75f;
    return rows;
}

TEST(Curves, StraightCurvesAreBandsOfTheirWidth) {
    // Width 0.25 of a 2-unit window on 64 pixels: 8 rows.
    EXPECT_NEAR(bandRows("Shape \"curve\" \"point P\" [-2 0 5  -1 0 5  1 0 5  2 0 5] \"float width\" 0.25 \"string type\" \"cylinder\""), 8, 1);
    EXPECT_NEAR(bandRows("Shape \"curve\" \"point P\" [-2 0 5  -1 0 5  1 0 5  2 0 5] \"float width\" 0.25"), 8, 1);
    EXPECT_NEAR(bandRows("Shape \"curve\" \"point P\" [-2 0 5  0 0 5  2 0 5] \"integer degree\" 2 \"float width\" 0.25 "
                         "\"string type\" \"ribbon\" \"normal N\" [0 0 -1  0 0 -1]"),
                8, 1);
    EXPECT_NEAR(bandRows("Shape \"curve\" \"point P\" [-3 0 5  -2 0 5  -1 0 5  0 0 5  1 0 5  2 0 5  3 0 5] \"string basis\" \"bspline\" "
                         "\"float width\" 0.25"),
                8, 1);
    // Width scales with the transform, and width0/width1 taper it (0.5 wide in the middle of 0..1).
    EXPECT_NEAR(bandRows("Scale 2 2 2\nShape \"curve\" \"point P\" [-1 0 2.5  -0.5 0 2.5  0.5 0 2.5  1 0 2.5] \"float width\" 0.125"), 8, 1);
    EXPECT_NEAR(bandRows("Shape \"curve\" \"point P\" [-1 0 5  -0.333 0 5  0.333 0 5  1 0 5] \"float width0\" 0 \"float width1\" 0.5"),
                8, 1);
}

// A curve is split into 2^splitdepth pieces (pbrt's default 3) for Embree: the pieces are the same
// curve, and a hit's u still runs along the whole of it. An S-shaped Bezier in the plane z = 5,
// 0.1 wide, hit straight on at points of the curve computed here: the hit is on that point, its u
// the point's parameter, its v the middle of the width. (Embree's u is the parameter along its
// flattened ribbon: unsplit, or split once, it is 0.008 off where this curve bends hardest, which
// the default's 8 pieces bring under 0.002.)
TEST(Curves, SplitPiecesAreTheCurveAndCarryItsParameter) {
    const Vec3f c[4] = {{-2, -1, 5}, {-1, 2, 5}, {1, -2, 5}, {2, 1, 5}};
    const auto at = [&](float t) {
        const float u = 1 - t;
        return u * u * u * c[0] + 3 * u * u * t * c[1] + 3 * u * t * t * c[2] + t * t * t * c[3];
    };
    test::TempDir dir;
    for (int depth : {-1, 3, 5}) {  // -1: not given
        const std::string split = depth < 0 ? "" : " \"integer splitdepth\" " + std::to_string(depth);
        const auto g = test::geometryOf(dir, "Material \"matte\"\nShape \"curve\" \"point P\" [-2 -1 5  -1 2 5  1 -2 5  2 1 5] "
                                             "\"float width\" 0.1" + split);
        for (float t : {0.06f, 0.3f, 0.5f, 0.71f, 0.94f}) {
            const Vec3f p = at(t);
            Intersection it;
            ASSERT_TRUE(test::trace(*g, {p.x, p.y, 0}, {0, 0, 1}, it)) << "splitdepth " << depth << " t " << t;
            EXPECT_NEAR(it.hit.p.z, 5, 1e-3) << "splitdepth " << depth << " t " << t;
            EXPECT_NEAR(it.hit.u, t, 2e-3) << "splitdepth " << depth << " t " << t;
            EXPECT_NEAR(it.hit.v, 0.5, 0.02) << "splitdepth " << depth << " t " << t;
        }
    }
    try {
        test::geometryOf(dir, "Shape \"curve\" \"point P\" [0 0 5  1 0 5  2 0 5  3 0 5] \"integer splitdepth\" 11");
        ADD_FAILURE() << "splitdepth 11 was taken";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("splitdepth must lie in [0, 10], got 11"), std::string::npos) << e.what();
    }
}

TEST(Curves, BadCurvesAndEmissionAreNamed) {
    test::TempDir dir;
    const std::string header = "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 4 \"integer yresolution\" 4\nWorldBegin\n";
    try {
        parseSceneFile(dir.write("b.pbrt", header + "Shape \"curve\" \"point P\" [0 0 0  1 0 0  2 0 0  3 0 0  4 0 0]\nWorldEnd\n"));
        ADD_FAILURE() << "5 points made a cubic Bezier curve";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("3k+1 points"), std::string::npos) << e.what();
    }
    const SceneDescription s = parseSceneFile(dir.write(
        "e.pbrt", header + "AreaLightSource \"diffuse\"\nShape \"curve\" \"point P\" [0 0 0  1 0 0  2 0 0  3 0 0]\nWorldEnd\n"));
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings.back().find("cannot emit"), std::string::npos) << s.warnings.back();
}

}  // namespace
}  // namespace lenslab
