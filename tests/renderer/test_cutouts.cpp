// Alpha cutouts: where a mesh's "alpha" is 0 rays pass through it, and "shadowalpha" does the same
// for shadow rays only.
#include <gtest/gtest.h>

#include "TestScenes.h"

namespace lenslab {
namespace {

// An orthographic view of a black square (z = 2) in front of an emitting one (z = 4) that fills
// the view: where the front square is cut, the emitter shows.
float visibleFraction(const std::string& cut) {
    test::TempDir dir;
    const std::string p = dir.write("cut.pbrt",
        "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"orthographic\" \"float screenwindow\" [-1 1 -1 1]\n"
        "Film \"image\" \"integer xresolution\" 32 \"integer yresolution\" 32\nWorldBegin\n"
        "Texture \"checks\" \"float\" \"checkerboard\" \"float uscale\" 2 \"float vscale\" 2 \"float tex1\" 1 \"float tex2\" 0\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-2 -2 4  -2 2 4  2 2 4  2 -2 4]\nAttributeEnd\n"
        "Material \"matte\" \"rgb Kd\" [0 0 0]\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-1 -1 2  1 -1 2  1 1 2  -1 1 2]\n"
        "  \"float uv\" [0 0 1 0 1 1 0 1] " + cut + "\nWorldEnd\n");
    return float(test::meanLum(test::render(p, 32, 32, 4).image));
}

TEST(Cutouts, AlphaZeroAndAlphaTexturesLetRaysThrough) {
    EXPECT_NEAR(visibleFraction(""), 0.0f, 1e-6);
    EXPECT_NEAR(visibleFraction("\"float alpha\" 0"), 1.0f, 1e-5);
    EXPECT_NEAR(visibleFraction("\"float alpha\" 1"), 0.0f, 1e-6);
    EXPECT_NEAR(visibleFraction("\"texture alpha\" \"checks\""), 0.5f, 0.02);  // two of four checks are holes
    EXPECT_NEAR(visibleFraction("\"float shadowalpha\" 0"), 0.0f, 1e-6);     // camera rays still stop
}

}  // namespace
}  // namespace lenslab
