// NURBS surfaces diced into triangles: a rational quadratic quarter circle swept along z is a
// quarter cylinder, exactly (up to the chords of the 30 x 30 dicing).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/SceneDescription.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

TEST(Nurbs, RationalQuarterCircleSweepsAQuarterCylinder) {
    test::TempDir dir;
    const double w = std::sqrt(0.5);
    // Control rows along u: (1,0) (1,1) (0,1) with weights 1, 1/sqrt2, 1; two rows in v at z = 0 and 2.
    std::string pw;
    for (double z : {0.0, 2.0})
        for (int i = 0; i < 3; ++i) {
            const double x = i < 2 ? 1 : 0, y = i > 0 ? 1 : 0, wi = i == 1 ? w : 1;
            pw += std::to_string(x * wi) + " " + std::to_string(y * wi) + " " + std::to_string(z * wi) + " " + std::to_string(wi) + "  ";
        }
    const std::string p = dir.write("n.pbrt", "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
                                              "WorldBegin\nShape \"nurbs\" \"integer nu\" 3 \"integer nv\" 2 \"integer uorder\" 3 \"integer vorder\" 2\n"
                                              "  \"float uknots\" [0 0 0 1 1 1] \"float vknots\" [0 0 1 1] \"float Pw\" [" + pw + "]\nWorldEnd\n");
    const SceneDescription s = parseSceneFile(p);
    ASSERT_EQ(s.shapes.size(), 1u);
    const Shape& shape = *s.shapes[0].shape;
    ASSERT_EQ(shape.primitiveCount(), 2u * 30 * 30);
    double area = 0;
    for (std::size_t t = 0; t < shape.primitiveCount(); ++t) {
        area += shape.primitiveArea(t);
        const ShapeSample x = shape.samplePrimitive(t, 0.3f, 0.6f);
        const double r = std::hypot(x.p.x, x.p.y);
        ASSERT_GT(r, 1 - 5e-4) << t;  // within the chord sag of 3-degree steps
        ASSERT_LT(r, 1 + 1e-5) << t;
        ASSERT_GE(x.p.z, -1e-6);
        ASSERT_LE(x.p.z, 2 + 1e-6);
    }
    EXPECT_NEAR(area, M_PI / 2 * 2, 2e-3);
}

TEST(Nurbs, BadKnotVectorsAreNamed) {
    test::TempDir dir;
    const std::string p = dir.write("b.pbrt", "Camera \"perspective\"\nWorldBegin\nShape \"nurbs\" \"integer nu\" 2 \"integer nv\" 2 "
                                              "\"integer uorder\" 2 \"integer vorder\" 2 \"float uknots\" [0 0 1] "
                                              "\"float vknots\" [0 0 1 1] \"point P\" [0 0 0 1 0 0 0 1 0 1 1 0]\nWorldEnd\n");
    try {
        parseSceneFile(p);
        ADD_FAILURE() << "a short knot vector was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("uknots needs nu + uorder = 4 values, got 3"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
