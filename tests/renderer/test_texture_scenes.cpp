// Textures in whole scenes: a checkered sphere lands where pbrt-v3's (u, v) conventions put its
// checks, and Texture names are scoped by AttributeBegin/AttributeEnd.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/SceneDescription.h"
#include "TestScenes.h"
#include "prescription/Pi.h"

namespace lenslab {
namespace {

// The camera looks along +y from (0, -5, 0), up +z: by pbrt-v3's LookAt, the image's right is
// world -x. A matte sphere under a uniform white sky reflects its albedo exactly (nothing shades a
// convex object), so each pixel shows the check's colour.
const char* kCheckedSphere =
    "LookAt 0 -5 0  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" 30\n"
    "Film \"image\" \"integer xresolution\" 48 \"integer yresolution\" 48\n"
    "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
    "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 4\n"
    "  \"rgb tex1\" [0.8 0.1 0.1] \"rgb tex2\" [0.1 0.1 0.8]\n"
    "Material \"matte\" \"texture Kd\" \"checks\"\nShape \"sphere\"\nWorldEnd\n";

struct ExpectedCheck {
    bool hit = false, clear = false, tex1 = false;
};

// pbrt-v3 for pixel (px, py) of an n x n image: the camera ray, the unit sphere's
// u = phi / 2pi and v = (theta - pi) / (0 - pi) with theta = acos z (zmin -1, zmax 1), and
// Checkerboard2D: floor(8u) + floor(4v) even gives tex1. `clear` when the point is well inside a
// check and not at a grazing angle.
ExpectedCheck pbrtCheck(int px, int py, int n) {
    const double tanHalf = std::tan(15 * kPi / 180);
    const double sx = ((px + 0.5) / n * 2 - 1) * tanHalf, sy = (1 - (py + 0.5) / n * 2) * tanHalf;
    // camera x = up x dir = (0,0,1) x (0,1,0) = (-1, 0, 0); camera y = (0, 0, 1); z = (0, 1, 0).
    double d[3] = {-sx, 1, sy};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& c : d) c /= len;
    const double o[3] = {0, -5, 0};
    const double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2], c = 25 - 1;
    const double disc = b * b - c;
    ExpectedCheck e;
    if (disc <= 0) return e;
    const double t = -b - std::sqrt(disc);
    const double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    e.hit = true;
    double phi = std::atan2(p[1], p[0]);
    if (phi < 0) phi += 2 * kPi;
    const double u = phi / (2 * kPi), v = (std::acos(p[2]) - kPi) / (0 - kPi);
    const double s = 8 * u, tt = 4 * v;
    const double fs = s - std::floor(s), ft = tt - std::floor(tt);
    const double cosView = -(p[0] * d[0] + p[1] * d[1] + p[2] * d[2]);
    e.clear = fs > 0.2 && fs < 0.8 && ft > 0.2 && ft < 0.8 && cosView > 0.4;
    e.tex1 = (long(std::floor(s)) + long(std::floor(tt))) % 2 == 0;
    return e;
}

TEST(TextureScenes, CheckeredSphereMatchesPbrtV3Conventions) {
    test::TempDir dir;
    const int n = 48;
    const Image im = test::render(dir.write("s.pbrt", kCheckedSphere), n, n, 16).image;
    int checked = 0, tex1Seen = 0;
    for (int py = 0; py < n; ++py)
        for (int px = 0; px < n; ++px) {
            const ExpectedCheck e = pbrtCheck(px, py, n);
            if (!e.hit || !e.clear) continue;
            const float* rgb = &im.rgb[(std::size_t(py) * n + px) * 3];
            const bool red = rgb[0] > rgb[2];
            EXPECT_EQ(red, e.tex1) << "pixel " << px << "," << py << " rgb " << rgb[0] << " " << rgb[1] << " " << rgb[2];
            ++checked;
            tex1Seen += e.tex1;
        }
    EXPECT_GT(checked, 300);
    EXPECT_GT(tex1Seen, 100);
    EXPECT_LT(tex1Seen, checked - 100);
}

const char* kTextureHeader = "LookAt 0 -5 0  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" 10\n"
                      "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                      "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n";

TEST(TextureScenes, AttributeEndForgetsTexturesDeclaredInside) {
    test::TempDir dir;
    const std::string inner = dir.write("inner.pbrt", std::string(kTextureHeader) +
        "AttributeBegin\nTexture \"t\" \"spectrum\" \"constant\" \"rgb value\" [1 0 0]\nAttributeEnd\n"
        "Material \"matte\" \"texture Kd\" \"t\"\nWorldEnd\n");
    EXPECT_NE(test::sceneErrorOf(inner).find("inner.pbrt:9: Material \"matte\": parameter \"Kd\" names an undeclared spectrum texture \"t\""),
              std::string::npos)
        << test::sceneErrorOf(inner);
    // TransformBegin/End does not scope textures.
    const std::string transformBlock = dir.write("transform.pbrt", std::string(kTextureHeader) +
        "TransformBegin\nTexture \"t\" \"spectrum\" \"constant\" \"rgb value\" [1 0 0]\nTransformEnd\n"
        "Material \"matte\" \"texture Kd\" \"t\"\nWorldEnd\n");
    EXPECT_EQ(test::sceneErrorOf(transformBlock), "(no error)");
}

TEST(TextureScenes, RedefinitionInsideABlockEndsWithIt) {
    test::TempDir dir;
    // The sphere fills the view: the centre pixel shows the albedo of the outer texture "t"
    // (green); the red redefinition lives only inside the block. The float texture "t" is a
    // separate name.
    const std::string scene = dir.write("s.pbrt", std::string(kTextureHeader) +
        "Texture \"t\" \"spectrum\" \"constant\" \"rgb value\" [0.1 0.7 0.1]\n"
        "Texture \"t\" \"float\" \"constant\" \"float value\" 0.5\n"
        "AttributeBegin\nTexture \"t\" \"spectrum\" \"constant\" \"rgb value\" [0.7 0.1 0.1]\nAttributeEnd\n"
        "Material \"matte\" \"texture Kd\" \"t\"\nShape \"sphere\"\nWorldEnd\n");
    const Image im = test::render(scene, 8, 8, 16).image;
    const float* rgb = &im.rgb[(4 * 8 + 4) * 3];
    EXPECT_NEAR(rgb[1], 0.7f, 0.05f);
    EXPECT_NEAR(rgb[0], 0.1f, 0.05f);
}

}  // namespace
}  // namespace lenslab
