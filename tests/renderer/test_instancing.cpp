// ObjectBegin / ObjectEnd / ObjectInstance: an object drawn at every instance's transform, hits
// brought back to world space, one copy of the object in memory however many instances, and
// pbrt-v3's rules (no area lights inside objects, no nesting, known names only).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

using test::trace;


TEST(Instancing, ObjectAppearsAtEveryInstanceTransform) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir,
        "ObjectBegin \"ball\"\n  Translate 0 0 1\n  Shape \"sphere\" \"float radius\" 0.5\nObjectEnd\n"
        "AttributeBegin\n  Translate -2 0 4\n  ObjectInstance \"ball\"\nAttributeEnd\n"
        "AttributeBegin\n  Translate 2 0 4\n  Scale 1 3 1\n  ObjectInstance \"ball\"\nAttributeEnd\n"
        "AttributeBegin\n  Translate 0 0 8\n  Rotate 90 0 1 0\n  ObjectInstance \"ball\"\nAttributeEnd\n");
    Intersection it;
    // The first: centre (-2, 0, 5), radius 0.5.
    ASSERT_TRUE(trace(*g, {-2, 0, 0}, {0, 0, 1}, it));
    EXPECT_NEAR(it.t, 4.5, 1e-5);
    EXPECT_NEAR(it.hit.ng.z, -1, 1e-5);
    // The second, stretched 3 times along y: its top at y = 1.5, normals by the inverse transpose.
    ASSERT_TRUE(trace(*g, {2, 5, 5}, {0, -1, 0}, it));
    EXPECT_NEAR(it.hit.p.y, 1.5, 1e-5);
    ASSERT_TRUE(trace(*g, {2.3f, 0.8f, 0}, {0, 0, 1}, it));
    const Vec3f q = it.hit.p - Vec3f{2, 0, 5};
    EXPECT_NEAR(q.x * q.x + q.y * q.y / 9 + q.z * q.z, 0.25, 1e-5);
    EXPECT_GT(dot(it.hit.ng, normalize(Vec3f{q.x, q.y / 9, q.z})), 0.99999f);
    // The third: the object's offset (0 0 1) turned by 90 degrees about y lands at x = +1.
    ASSERT_TRUE(trace(*g, {1, 0, 0}, {0, 0, 1}, it));
    EXPECT_NEAR(it.t, 7.5, 1e-5);
    // (u, v) stay those of the object's own sphere: the world offset (0, 0.3, -0.4) from the centre
    // is (0.4, 0.3, 0) there, at phi = atan2(0.3, 0.4) on the equator.
    ASSERT_TRUE(trace(*g, {1, 0.3f, 0}, {0, 0, 1}, it));
    EXPECT_NEAR(it.hit.p.z, 7.6, 1e-5);
    EXPECT_NEAR(it.hit.u, std::atan2(0.3, 0.4) / (2 * M_PI), 1e-5);
    EXPECT_NEAR(it.hit.v, 0.5, 1e-5);
    EXPECT_NEAR(it.hit.ng.y, 0.6, 1e-5);
    EXPECT_FALSE(trace(*g, {0, 0, 0}, {0, 0, 1}, it));  // nothing at the object's own place
}

TEST(Instancing, InstancesRenderWhereTheyArePlaced) {
    test::TempDir dir;
    // Dark balls against a bright sky: each instance darkens the pixel at its centre.
    const Image im = test::render(test::shapeScene(dir,
        "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
        "ObjectBegin \"ball\"\n  Material \"matte\" \"rgb Kd\" [0 0 0]\n  Shape \"sphere\" \"float radius\" 0.3\nObjectEnd\n"
        "AttributeBegin\n  Translate -1 1 5\n  ObjectInstance \"ball\"\nAttributeEnd\n"
        "AttributeBegin\n  Translate 1 -1 5\n  ObjectInstance \"ball\"\nAttributeEnd\n"), 64, 64, 4).image;
    const double s = test::pixelsPerUnitAt(5);
    // World +x is image right for this camera (pbrt's LookAt), +y up.
    EXPECT_NEAR(test::lum(im, int(32 - s), int(32 - s)), 0, 1e-6);
    EXPECT_NEAR(test::lum(im, int(32 + s), int(32 + s)), 0, 1e-6);
    EXPECT_NEAR(test::lum(im, int(32 + s), int(32 - s)), 1, 1e-6);
    EXPECT_NEAR(test::lum(im, 32, 32), 1, 1e-6);
    // At 4 spp the count of pixels over half bright runs 15-19 below the area over seeds 0-9 with
    // either camera sampler (edge pixels estimated from 4 samples): 15% of the balls' area.
    EXPECT_NEAR(test::brightPixels(im, 0.5f), 64 * 64 - 2 * M_PI * 0.09 * s * s, 0.15 * 2 * M_PI * 0.09 * s * s);
}

long residentKb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return 0;
}

// A subdivided icosahedron of 81,920 triangles as an object, placed once or 10,000 times: the
// instances cost a few hundred bytes each, never another copy of the mesh (which would need
// gigabytes).
TEST(Instancing, TenThousandInstancesShareOneMesh) {
    test::TempDir dir;
    const std::string object =
        "ObjectBegin \"ico\"\nShape \"loopsubdiv\" \"integer nlevels\" 6 \"point P\" "
        "[0 -0.526 0.851  0 0.526 0.851  0 -0.526 -0.851  0 0.526 -0.851  0.851 0 -0.526  0.851 0 0.526 "
        "-0.851 0 -0.526  -0.851 0 0.526  -0.526 0.851 0  0.526 0.851 0  -0.526 -0.851 0  0.526 -0.851 0] "
        "\"integer indices\" [1 0 5  1 7 0  1 5 9  1 9 8  1 8 7  0 7 10  0 10 11  0 11 5  5 11 4  5 4 9  "
        "9 4 3  9 3 8  8 3 6  8 6 7  7 6 10  2 3 4  2 4 11  2 11 10  2 10 6  2 6 3]\nObjectEnd\n";
    const auto grow = [&](int instances) {
        std::ostringstream world;
        world << object;
        for (int i = 0; i < instances; ++i)
            world << "AttributeBegin\nTranslate " << (i % 100) * 3 << " " << (i / 100) * 3 << " 20\nObjectInstance \"ico\"\nAttributeEnd\n";
        SceneDescription scene = test::parseWorld(dir, world.str());
        const long before = residentKb();
        SceneGeometry g(scene);
        Intersection it;
        EXPECT_TRUE(trace(g, {0, 0, 0}, {0, 0, 1}, it));
        const long kb = residentKb() - before;
        std::cout << instances << " instance(s): geometry grew the process by " << kb / 1024.0 << " MiB\n";
        return kb;
    };
    const long many = grow(10000), one = grow(1);
    EXPECT_LT(many - one, 64 * 1024) << "10,000 instances must not copy the mesh";
}

TEST(Instancing, AreaLightsInsideObjectsAreIgnoredWithAWarning) {
    test::TempDir dir;
    const SceneDescription s = test::parseWorld(dir,
        "ObjectBegin \"lamp\"\nAreaLightSource \"diffuse\" \"rgb L\" [5 5 5]\nShape \"disk\"\nObjectEnd\n"
        "ObjectInstance \"lamp\"\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_FALSE(s.objects[0].shapes[0].emission);
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings.back().find("s.pbrt:7: Shape \"disk\": area lights inside ObjectBegin"), std::string::npos)
        << s.warnings.back();
}

// As pbrt-v3: a second ObjectBegin of a name replaces the object for the instances that follow.
TEST(Instancing, RedefinedObjectsServeLaterInstances) {
    test::TempDir dir;
    const SceneDescription s = test::parseWorld(dir,
        "ObjectBegin \"a\"\nShape \"sphere\"\nObjectEnd\nObjectInstance \"a\"\n"
        "ObjectBegin \"a\"\nShape \"disk\"\nShape \"disk\"\nObjectEnd\nObjectInstance \"a\"\n");
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.objects[s.instances[0].object].shapes.size(), 1u);
    EXPECT_EQ(s.objects[s.instances[1].object].shapes.size(), 2u);
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings.back().find("s.pbrt:9: ObjectBegin \"a\": redefines object \"a\""), std::string::npos)
        << s.warnings.back();
}

TEST(Instancing, BadObjectUseIsAnError) {
    test::TempDir dir;
    const auto error = [&](const std::string& world) { return test::sceneErrorOf(test::shapeScene(dir, world)); };
    std::string e = error("ObjectInstance \"nothing\"");
    EXPECT_NE(e.find("s.pbrt:5: ObjectInstance \"nothing\": unknown object \"nothing\""), std::string::npos) << e;
    e = error("ObjectBegin \"a\"\nObjectBegin \"b\"\nObjectEnd\nObjectEnd");
    EXPECT_NE(e.find("s.pbrt:6: ObjectBegin \"b\": inside the definition of object \"a\""), std::string::npos) << e;
    e = error("ObjectBegin \"a\"\nObjectInstance \"a\"\nObjectEnd");
    EXPECT_NE(e.find("s.pbrt:6: ObjectInstance \"a\": inside the definition"), std::string::npos) << e;
    e = error("ObjectEnd");
    EXPECT_NE(e.find("s.pbrt:5: ObjectEnd: without a matching ObjectBegin"), std::string::npos) << e;
    e = error("ObjectBegin \"a\"\nAttributeBegin\nObjectEnd\nAttributeEnd");
    EXPECT_NE(e.find("s.pbrt:7: ObjectEnd: AttributeBegin/AttributeEnd inside object \"a\" do not pair up"), std::string::npos) << e;
}

}  // namespace
}  // namespace lenslab
