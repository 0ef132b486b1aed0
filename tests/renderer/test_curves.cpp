// Curves: Embree's curve primitives behind pbrt-v3's "curve" shape. A straight curve of width w seen
// through an orthographic window is a band w tall, whatever its type, basis and degree.
#include <gtest/gtest.h>

#include "scene/SceneDescription.h"
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
