// Scene syntax: transforms and shapes land where pbrt-v3 puts them; bad scenes give clear errors
// naming the file, the line and the directive.
#include <gtest/gtest.h>

#include "scene/SceneDescription.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

const char* kParserHeader = "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                      "Film \"image\" \"integer xresolution\" 16 \"integer yresolution\" 16\n";


// Renders (tiny) and returns the message of the SceneError it must throw.
std::string renderErrorOf(const std::string& path, RenderSettings s = {}) {
    s.scenePath = path;
    if (!s.width) s.width = 8;
    if (!s.height) s.height = 8;
    s.spp = 1;
    s.threads = 1;
    try {
        renderScene(s);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SceneParser, TransformsPlaceShapesAsPbrtDoes) {
    test::TempDir dir;
    const std::string scene = dir.write("s.pbrt", std::string(kParserHeader) +
        "WorldBegin\n"
        "AttributeBegin\n  Translate 1 2 3\n  Scale 2 2 2\n  Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n"
        "TransformBegin\n  Rotate 90 0 0 1\n"
        "  Shape \"trianglemesh\" \"integer indices\" [0 1 2] \"point P\" [1 0 0  0 1 0  0 0 1]\nTransformEnd\n"
        "Shape \"sphere\"\n"
        "WorldEnd\n");
    const SceneDescription s = parseSceneFile(scene);
    ASSERT_EQ(s.shapes.size(), 3u);
    // Points drawn on each shape: the sphere's equator at phi = 0, the triangle's first corner.
    const Vec3f onBall = s.shapes[0].shape->samplePrimitive(0, 0.5f, 0).p;
    EXPECT_NEAR(onBall.x, 2, 1e-5);  // centre (1, 2, 3), radius 2 * 0.5
    EXPECT_NEAR(onBall.y, 2, 1e-5);
    EXPECT_NEAR(onBall.z, 3, 1e-5);
    EXPECT_NEAR(s.shapes[0].shape->primitiveArea(0), 4 * M_PI, 1e-4);
    const Vec3f corner = s.shapes[1].shape->samplePrimitive(0, 1, 0).p;
    EXPECT_NEAR(corner.x, 0, 1e-6);  // (1,0,0) rotated 90 degrees about z
    EXPECT_NEAR(corner.y, 1, 1e-6);
    const Vec3f onUnitBall = s.shapes[2].shape->samplePrimitive(0, 0.5f, 0).p;  // attributes restored
    EXPECT_NEAR(onUnitBall.x, 1, 1e-6);
    EXPECT_NEAR(onUnitBall.y, 0, 1e-6);
    EXPECT_EQ(s.camera.type, "perspective");
    EXPECT_EQ(s.film.xresolution, 16);
}

TEST(SceneParser, IncludeReachesAnywhereUnlessConfined) {
    test::TempDir dir;
    dir.write("parts/ball.pbrt", "Shape \"sphere\" \"float radius\" 2\n");
    const std::string up = dir.write("scene/s.pbrt", std::string(kParserHeader) + "WorldBegin\nInclude \"../parts/ball.pbrt\"\nWorldEnd\n");
    EXPECT_EQ(parseSceneFile(up).shapes.size(), 1u);  // the command line: the user's own files
    SceneParseOptions confined;
    confined.confined = true;
    try {
        parseSceneFile(up, confined);
        ADD_FAILURE() << "a confined scene reached outside its folder";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("outside the scene's folder"), std::string::npos) << e.what();
    }
    const std::string inside = dir.write("s2.pbrt", std::string(kParserHeader) + "WorldBegin\nInclude \"parts/ball.pbrt\"\nWorldEnd\n");
    EXPECT_EQ(parseSceneFile(inside).shapes.size(), 1u);
}

// pbrt reads an Include as tokens spliced into the stream: the included file's last directive
// takes the parameters that follow the Include (pbrt-v4's smoke-plume scene relies on it).
TEST(SceneParser, IncludedDirectiveTakesParametersThatFollow) {
    test::TempDir dir;
    dir.write("parts/ball.pbrt", "AttributeBegin\nShape \"sphere\"\n");
    const std::string ok = dir.write("ok.pbrt", std::string(kParserHeader) +
        "WorldBegin\nInclude \"parts/ball.pbrt\"\n  \"float radius\" 2\nAttributeEnd\nWorldEnd\n");
    const SceneDescription s = parseSceneFile(ok);
    EXPECT_EQ(s.shapes.size(), 1u);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    // A bad value names the line in the including file, where it stands.
    const std::string bad = dir.write("bad.pbrt", std::string(kParserHeader) +
        "WorldBegin\nInclude \"parts/ball.pbrt\"\n  \"float radius\" [ x ]\nAttributeEnd\nWorldEnd\n");
    const std::string e = test::sceneErrorOf(bad);
    EXPECT_NE(e.find("bad.pbrt:6: Shape \"sphere\": bad number 'x'"), std::string::npos) << e;
}

TEST(SceneErrors, ErrorInIncludedFileNamesItsLine) {
    test::TempDir dir;
    dir.write("parts/t.pbrt", "\n\nTranslate 1 x 2\n");
    const std::string p = dir.write("s.pbrt", std::string(kParserHeader) + "WorldBegin\nInclude \"parts/t.pbrt\"\nWorldEnd\n");
    const std::string e = test::sceneErrorOf(p);
    EXPECT_NE(e.find("t.pbrt:3: Translate: bad number 'x'"), std::string::npos) << e;
}

TEST(SceneErrors, IncludeCycle) {
    test::TempDir dir;
    dir.write("cycle.pbrt", "Include \"cycle.pbrt\"\n");  // last: its file is done when it nests
    const std::string p = dir.write("s.pbrt", std::string(kParserHeader) + "WorldBegin\nInclude \"cycle.pbrt\"\n");
    const std::string e = test::sceneErrorOf(p);
    EXPECT_NE(e.find("nested deeper than 32"), std::string::npos) << e;
}

TEST(SceneErrors, UnknownDirectiveNamesFileLineAndDirective) {
    test::TempDir dir;
    const std::string p = dir.write("bad.pbrt", std::string(kParserHeader) + "WorldBegin\n\nMakeItPretty 3\nWorldEnd\n");
    const std::string e = test::sceneErrorOf(p);
    EXPECT_NE(e.find("bad.pbrt:6"), std::string::npos) << e;
    EXPECT_NE(e.find("MakeItPretty"), std::string::npos) << e;
}

TEST(SceneErrors, MissingIncludeFile) {
    test::TempDir dir;
    const std::string p = dir.write("s.pbrt", std::string(kParserHeader) + "WorldBegin\nInclude \"nothere.pbrt\"\nWorldEnd\n");
    const std::string e = test::sceneErrorOf(p);
    EXPECT_NE(e.find("s.pbrt:5: Include"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot open 'nothere.pbrt'"), std::string::npos) << e;
    EXPECT_NE(test::sceneErrorOf(dir.path() + "/missing.pbrt").find("cannot open scene file"), std::string::npos);
}

TEST(SceneErrors, BadNumbers) {
    test::TempDir dir;
    const std::string a = dir.write("a.pbrt", std::string(kParserHeader) + "WorldBegin\nTranslate 1 2 x3\nWorldEnd\n");
    EXPECT_NE(test::sceneErrorOf(a).find("a.pbrt:5: Translate: bad number 'x3'"), std::string::npos) << test::sceneErrorOf(a);
    const std::string b = dir.write("b.pbrt", std::string(kParserHeader) + "WorldBegin\nShape \"sphere\" \"float radius\" [ 1e999 ]\nWorldEnd\n");
    EXPECT_NE(test::sceneErrorOf(b).find("bad number '1e999'"), std::string::npos) << test::sceneErrorOf(b);
    const std::string c = dir.write("c.pbrt", std::string(kParserHeader) + "WorldBegin\nShape \"sphere\" \"float radius\" -1\nWorldEnd\n");
    EXPECT_NE(test::sceneErrorOf(c).find("radius must be positive"), std::string::npos) << test::sceneErrorOf(c);
    const std::string d = dir.write("d.pbrt", std::string(kParserHeader) +
        "WorldBegin\nShape \"trianglemesh\" \"integer indices\" [0 1 5] \"point P\" [0 0 0 1 0 0 0 1 0]\nWorldEnd\n");
    EXPECT_NE(test::sceneErrorOf(d).find("index 5 out of range"), std::string::npos) << test::sceneErrorOf(d);
}

TEST(SceneErrors, AbsurdResolution) {
    test::TempDir dir;
    const std::string p = dir.write("r.pbrt", "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 100000 "
                                              "\"integer yresolution\" 10\nWorldBegin\nWorldEnd\n");
    RenderSettings s;
    s.scenePath = p;
    s.threads = 1;
    try {
        renderScene(s);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("r.pbrt:2: Film \"image\": resolution 100000x10 is out of range"), std::string::npos)
            << e.what();
    }
    RenderSettings zero;
    zero.width = 0;
    EXPECT_NE(renderErrorOf(p, zero).find("out of range"), std::string::npos);
}

TEST(SceneErrors, UnsupportedFeaturesAreNamedNeverIgnored) {
    test::TempDir dir;
    const auto check = [&](const std::string& world, const std::string& expected) {
        const std::string p = dir.write("u.pbrt", std::string(kParserHeader) + "WorldBegin\n" + world + "\nWorldEnd\n");
        const std::string e = test::sceneErrorOf(p);
        EXPECT_NE(e.find(expected), std::string::npos) << e;
    };
    check("Shape \"plymesh\" \"string filename\" \"x.ply\"", "cannot open 'x.ply'");
    check("Material \"fourier\" \"string bsdffile\" \"x.bsdf\"", "material \"fourier\" is not supported");
    check("ObjectBegin \"x\"", "u.pbrt:5: ObjectBegin \"x\": not closed by ObjectEnd");
    check("AttributeBegin\nShape \"sphere\"", "not closed by AttributeEnd");
}

TEST(SceneErrors, RealisticCameraRangesAreNamed) {
    test::TempDir dir;
    const auto scene = [&](const std::string& params) {
        return dir.write("cam.pbrt", test::courseCamera("dgauss.50mm.dat", params) + "\nFilm \"image\"\nWorldBegin\nWorldEnd\n");
    };
    const std::string fstop = renderErrorOf(scene("\"float fstop\" 1.2 \"float focaldistance\" 3000"));
    EXPECT_NE(fstop.find("cam.pbrt:2: Camera \"realistic\""), std::string::npos) << fstop;
    EXPECT_NE(fstop.find("range"), std::string::npos) << fstop;
    const std::string focus = renderErrorOf(scene("\"float fstop\" 4 \"float focaldistance\" 20"));
    EXPECT_NE(focus.find("closest"), std::string::npos) << focus;
    EXPECT_EQ(renderErrorOf(scene("\"float fstop\" 4 \"float focaldistance\" 3000")), "(no error)");
    const std::string missing = renderErrorOf(dir.write("m.pbrt", "Camera \"realistic\" \"string specfile\" \"nolens.dat\"\n"
                                                                  "WorldBegin\nWorldEnd\n"));
    EXPECT_NE(missing.find("cannot open 'nolens.dat' (looked for " + dir.path() + "/nolens.dat" + ")"),
              std::string::npos) << missing;
}

}  // namespace
}  // namespace lenslab
