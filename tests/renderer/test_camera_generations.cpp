// The realistic camera's three generations of parameters, each with its own conventions: the course's
// (specfile, fstop, focaldistance, filmdiagonal: camera space in millimetres), the later course's
// (filmdistance, aperture_diameter, filmdiag, hither, yon) and pbrt-v3/v4's (lensfile in metres,
// aperturediameter, focusdistance from the film, aperture shapes). Lens files resolve like every
// scene file and are never looked up elsewhere.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "cameras/ApertureShape.h"
#include "cameras/CameraFactory.h"
#include "settings/LensAnalysis.h"
#include "firstorder/PbrtPupilBox.h"
#include "cameras/RealisticCamera.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

std::string exactText(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

// A checker wall 3 m ahead under a uniform sky and a glowing ball 1.5 m ahead, off the axis; the
// scenes put their Film before it. Units: metres.
const char* kWorld =
    "PixelFilter \"box\"\nIntegrator \"directlighting\" \"integer maxdepth\" 1\n"
    "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
    "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 40 \"float vscale\" 40 \"rgb tex1\" [0.9 0.9 0.9] "
    "\"rgb tex2\" [0.1 0.1 0.1]\nMaterial \"matte\" \"texture Kd\" \"c\"\n"
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-3 -3 3  3 -3 3  3 3 3  -3 3 3] "
    "\"float uv\" [0 0 1 0 1 1 0 1]\n"
    "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 3 2]\nTranslate 0.1 0.05 1.5\n"
    "Shape \"sphere\" \"float radius\" 0.05\nAttributeEnd\nWorldEnd\n";

std::string lensfileCamera(const std::string& lens, const std::string& params) {
    return "Camera \"realistic\" \"string lensfile\" \"" + test::lensPath(lens) + "\" " + params;
}

std::string renderError(const std::string& scene) {
    try {
        test::render(scene, 8, 8, 1);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

struct Comparison {
    double meanA = 0, meanB = 0, meanAbsDifference = 0, maxAbsDifference = 0;
};

Comparison compare(const Image& a, const Image& b) {
    Comparison c;
    const int n = a.width * a.height;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const double va = test::lum(a, x, y), vb = test::lum(b, x, y);
            c.meanA += va / n;
            c.meanB += vb / n;
            c.meanAbsDifference += std::fabs(va - vb) / n;
            c.maxAbsDifference = std::max(c.maxAbsDifference, std::fabs(va - vb));
        }
    return c;
}

double metadataNumber(const RenderOutput& out, const std::string& key) { return std::stod(out.metadata.at(key)); }

TEST(CameraGenerations, CourseMillimetresAndLensfileMetresDrawTheSamePicture) {
    test::TempDir dir;
    const double stop = 8, focusFromVertex = 1500;  // mm
    const std::string courseParams = "\"float aperture_diameter\" " + exactText(stop) + " \"float focaldistance\" " +
                                     exactText(focusFromVertex) + " \"float filmdiag\" 30\nFilm \"image\"\n";
    const std::string course = dir.write("course.pbrt", test::courseCamera("dgauss.50mm.dat", courseParams) + kWorld);
    const RenderOutput c = test::render(course, 48, 48, 16);
    EXPECT_EQ(c.metadata.at("cameraSpaceUnitMm"), "1");
    // pbrt-v3 measures the focus from the film, in metres: the same plane of focus. Its camera space
    // starts at the film, so the camera moves back by the film's depth to stand where the course's did.
    const double filmZ = metadataNumber(c, "filmZMm");
    const std::string pbrt = dir.write("pbrt.pbrt", "Translate 0 0 " + exactText(-filmZ / 1000) + "\n" +
        lensfileCamera("dgauss.50mm.dat", "\"float aperturediameter\" " + exactText(stop) + " \"float focusdistance\" " +
                                              exactText((focusFromVertex - filmZ) / 1000) +
                                              " \"bool simpleweighting\" false\nFilm \"image\" \"float diagonal\" 30\n") +
        kWorld);
    const RenderOutput p = test::render(pbrt, 48, 48, 16);
    EXPECT_EQ(p.metadata.at("cameraSpaceUnitMm"), "1000");
    EXPECT_EQ(p.metadata.at("cameraSpaceOrigin"), "film");
    EXPECT_EQ(c.metadata.at("cameraSpaceOrigin"), "front vertex");
    EXPECT_NEAR(metadataNumber(p, "filmZMm"), filmZ, 1e-3);
    const Comparison d = compare(c.image, p.image);
    RecordProperty("mean_course", exactText(d.meanA));
    RecordProperty("mean_lensfile", exactText(d.meanB));
    RecordProperty("max_pixel_difference", exactText(d.maxAbsDifference));
    EXPECT_GT(d.meanA, 0.01);
    EXPECT_NEAR(d.meanA / d.meanB, 1.0, 1e-3);
    EXPECT_LT(d.meanAbsDifference, 1e-3 * d.meanA);
    EXPECT_LT(d.maxAbsDifference, 0.1 * d.meanA);  // a sample or two may cross a check edge

    // The course's names without the Scale see the metre world from a thousand times closer.
    const std::string unscaled = dir.write("unscaled.pbrt",
        "Camera \"realistic\" \"string specfile\" \"" + test::lensPath("dgauss.50mm.dat") + "\" " + courseParams + kWorld);
    EXPECT_GT(compare(c.image, test::render(unscaled, 48, 48, 16).image).meanAbsDifference, 0.1 * d.meanA);
}

// pbrt-v3's simple weighting scales the radiometric weights by d^2 / A0 (film to rear vertex, its
// first exit-pupil box): the two renders of one lensfile scene, same samples, differ by exactly that
// factor everywhere, in both lens models; the course's names keep their centre at 1 instead.
TEST(CameraGenerations, LensfileSimpleWeightingIsPbrtV3sExposure) {
    test::TempDir dir;
    for (const std::string mode : {"exact", "thick"}) {
        SCOPED_TRACE(mode);
        const auto scene = [&](const char* simple) {
            return dir.write(std::string(simple) + mode + ".pbrt",
                lensfileCamera("dgauss.50mm.dat", "\"float aperturediameter\" 10 \"float focusdistance\" 3 "
                                                  "\"string mode\" \"" + mode + "\" \"bool simpleweighting\" " + simple) +
                "\nFilm \"image\" \"float diagonal\" 35\n" + kWorld);
        };
        const RenderOutput simple = test::render(scene("true"), 24, 24, 4), radiometric = test::render(scene("false"), 24, 24, 4);
        const double filmZ = metadataNumber(simple, "filmZMm");
        const LensSystem lens = withStopDiameter(loadLensSystem(test::lensPath("dgauss.50mm.dat")), 10);
        const double d = lens.rearZ() - filmZ, expected = d * d / pbrtFirstPupilBoxArea(lens, filmZ, 35);
        EXPECT_NEAR(expected, 11.7, 0.3);  // (about 37 mm to the film)^2 / its ~117 mm^2 box
        const Comparison c = compare(simple.image, radiometric.image);
        EXPECT_GT(c.meanB, 0.001);
        EXPECT_NEAR(c.meanA / c.meanB, expected, 1e-4 * expected);
        EXPECT_NE(simple.metadata.at("weighting").find("pbrt-v3"), std::string::npos);
    }
}

// The film at the distance the focus solve chose for D is the camera focused at D, ray for ray, in
// each model.
TEST(CameraGenerations, FilmDistancePlacesTheFilmWhereTheFocusSolvePutsIt) {
    const LensSystem lens = loadLensSystem(test::lensPath("dgauss.dat"));
    const double fstop = 4, focus = 2500;
    const LensAnalysis a = analyzeLens(lens, fstop, focus);
    for (const LensMode mode : {LensMode::Exact, LensMode::Thick}) {
        RealisticParams focused = realisticParams(test::lensPath("dgauss.dat"), fstop, focus);
        focused.mode = mode;
        focused.cameraUnitMm = 1;
        RealisticParams placed = focused;
        const double filmZ = mode == LensMode::Exact ? a.focus.imageZExact : a.focus.imageZThick;
        placed.settings.focusDistance.reset();
        placed.settings.filmDistance = Setting{lens.rearZ() - filmZ, "filmdistance"};
        const RealisticCamera f(focused, Transform(), 64, 48, 0), p(placed, Transform(), 64, 48, 0);
        EXPECT_NEAR(p.filmZ(), f.filmZ(), 1e-9);
        int compared = 0;
        for (double x : {3.5, 30.0, 60.5})
            for (double y : {2.5, 24.0, 45.5})
                for (float u : {0.1f, 0.5f, 0.85f}) {
                    CameraRay rf, rp;
                    const bool passF = f.generateRay(x, y, u, 1 - u, rf), passP = p.generateRay(x, y, u, 1 - u, rp);
                    ASSERT_EQ(passF, passP);
                    if (!passF) continue;
                    ++compared;
                    for (int k = 0; k < 3; ++k) {
                        EXPECT_NEAR(rp.origin[k], rf.origin[k], 1e-4);
                        EXPECT_NEAR(rp.direction[k], rf.direction[k], 1e-6);
                    }
                    EXPECT_NEAR(rp.weight / rf.weight, 1.0, 1e-6);
                }
        EXPECT_GT(compared, 20);
        // The thick-lens conjugate of that film is the plane of focus again (exactly, for the thick film).
        const double conjugate = thickLensFocusForFilm(lens, a.firstOrder, a.focus.imageZThick);
        EXPECT_NEAR(conjugate, focus, 1e-6 * focus);
    }
}

TEST(CameraGenerations, FilmDistanceUnderALensOverrideFocusesTheOtherLensWhereTheScenesLensWas) {
    test::TempDir dir;
    const LensSystem own = loadLensSystem(test::lensPath("dgauss.50mm.dat"));
    const LensAnalysis a = analyzeLens(own, 4, 3000);
    const std::string scene = dir.write("s.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"float filmdistance\" " + exactText(own.rearZ() - a.focus.imageZThick) +
                                                  " \"float aperture_diameter\" 10\n") + kWorld);
    EXPECT_EQ(test::render(scene, 8, 8, 1).metadata.at("filmPlacement").rfind("filmdistance ", 0), 0u);
    RenderSettings s;
    s.camera.lensFile = test::lensPath("dgauss.dat");
    const RenderOutput other = test::render(scene, 8, 8, 1, s);
    EXPECT_EQ(other.metadata.at("filmPlacement"), "focused");
    EXPECT_NEAR(metadataNumber(other, "focusDistanceMm"), 3000, 0.01);
}

TEST(CameraGenerations, ApertureDiameterIsTheStopOpeningOfTheSameFstop) {
    test::TempDir dir;
    const LensAnalysis a = analyzeLens(loadLensSystem(test::lensPath("dgauss.dat")), 5.6, 3000);
    const auto fstopOf = [&](const std::string& camera) {
        return metadataNumber(test::render(dir.write("a.pbrt", camera + "\n" + kWorld), 8, 8, 1), "fstop");
    };
    const std::string common = "\"float focaldistance\" 3000 ";
    EXPECT_NEAR(fstopOf(test::courseCamera("dgauss.dat", common + "\"float fstop\" 5.6")), 5.6, 1e-9);
    EXPECT_NEAR(fstopOf(test::courseCamera("dgauss.dat", common + "\"float aperture_diameter\" " + exactText(a.stopDiameter))),
                5.6, 1e-4);
    EXPECT_NEAR(fstopOf(lensfileCamera("dgauss.dat", common + "\"float aperturediameter\" " + exactText(a.stopDiameter))), 5.6,
                1e-4);
}

TEST(CameraGenerations, ContradictingParametersAreAnErrorNamingBoth) {
    test::TempDir dir;
    const std::string lens = "\"" + test::lensPath("dgauss.dat") + "\"";
    const auto check = [&](const std::string& params, const std::string& a, const std::string& b) {
        const std::string e = renderError(dir.write("c.pbrt", "Scale 1000 1000 1000\nCamera \"realistic\" " + params + "\n" + kWorld));
        EXPECT_NE(e.find("c.pbrt:2: Camera \"realistic\""), std::string::npos) << e;
        EXPECT_NE(e.find("\"" + a + "\" and \"" + b + "\""), std::string::npos) << e;
    };
    check("\"string specfile\" " + lens + " \"string lensfile\" " + lens, "specfile", "lensfile");
    check("\"string specfile\" " + lens + " \"float fstop\" 4 \"float aperture_diameter\" 10", "fstop", "aperture_diameter");
    check("\"string specfile\" " + lens + " \"float fstop\" 4 \"float aperturediameter\" 10", "fstop", "aperturediameter");
    check("\"string specfile\" " + lens + " \"float focaldistance\" 2000 \"float filmdistance\" 60", "focaldistance",
          "filmdistance");
    check("\"string lensfile\" " + lens + " \"float focaldistance\" 2000 \"float focusdistance\" 2", "focaldistance",
          "focusdistance");
    check("\"string specfile\" " + lens + " \"float filmdiagonal\" 35 \"float filmdiag\" 43", "filmdiagonal", "filmdiag");
}

// checkRenderSettings refuses what the render would refuse, with the render's message, without
// reading the world (here a mesh that does not exist) or measuring the exit pupil.
TEST(CameraGenerations, TheSettingsCheckRefusesWhatTheRenderRefusesWithoutTheWorld) {
    test::TempDir dir;
    const std::string world = "WorldBegin\nShape \"plymesh\" \"string filename\" \"absent.ply\"\nWorldEnd\n";
    const auto check = [&](const std::string& camera, const CameraOverrides& o) -> std::string {
        RenderSettings s;
        s.scenePath = dir.write("s.pbrt", "Scale 1000 1000 1000\n" + camera + "\n" + world);
        s.camera = o;
        try {
            checkRenderSettings(s);
        } catch (const SceneError& e) {
            const std::string message = e.what();
            s.scenePath = dir.write("s.pbrt", "Scale 1000 1000 1000\n" + camera + "\n" + kWorld);
            try {  // the render, with a world, says the same
                test::render(s.scenePath, 8, 8, 1, s);
                ADD_FAILURE() << "the render accepted what the check refused: " << message;
            } catch (const SceneError& r) {
                EXPECT_EQ(std::string(r.what()), message);
            }
            return message;
        }
        return "(no error)";
    };
    const std::string lens = "\"" + test::lensPath("telephoto.250mm.dat") + "\"";
    EXPECT_EQ(check("Camera \"realistic\" \"string specfile\" " + lens + " \"float fstop\" 8", {}), "(no error)");
    const std::string wide = check("Camera \"realistic\" \"string specfile\" " + lens + " \"float fstop\" 2.1", {});
    EXPECT_NE(wide.find("s.pbrt:2: Camera \"realistic\": fstop: f-number 2.1 is outside this lens's range f/5.6 to f/64"),
              std::string::npos) << wide;
    // The scene's f-number, fine for its own lens, checked against the lens that replaces it.
    CameraOverrides other;
    other.lensFile = test::lensPath("telephoto.250mm.dat");
    const std::string replaced =
        check("Camera \"realistic\" \"string specfile\" \"" + test::lensPath("dgauss.50mm.dat") + "\" \"float fstop\" 2.1", other);
    EXPECT_NE(replaced.find("fstop: f-number 2.1 is outside"), std::string::npos) << replaced;
    other.fstop = Setting{8, "field fstop"};
    EXPECT_EQ(check("Camera \"realistic\" \"string specfile\" \"" + test::lensPath("dgauss.50mm.dat") + "\" \"float fstop\" 2.1",
                    other),
              "(no error)");
    // Lens overrides on a camera without a lens, and a too-near focus.
    EXPECT_NE(check("Camera \"perspective\"", other).find("need a Camera \"realistic\""), std::string::npos);
    const std::string near =
        check("Camera \"realistic\" \"string specfile\" " + lens + " \"float fstop\" 8 \"float focaldistance\" 20", {});
    EXPECT_NE(near.find("s.pbrt:2: Camera \"realistic\": focaldistance"), std::string::npos) << near;
}

TEST(CameraGenerations, ALensFileIsResolvedFromTheSceneFolderAndNeverLookedUpElsewhere) {
    test::TempDir dir;
    // dgauss.dat is a bundled lens, but not in this scene's folder: an error naming the path tried.
    const std::string missing = renderError(dir.write("m.pbrt",
        "Camera \"realistic\" \"string specfile\" \"dgauss.dat\"\n" + std::string(kWorld)));
    EXPECT_NE(missing.find("m.pbrt:1: Camera \"realistic\""), std::string::npos) << missing;
    EXPECT_NE(missing.find("looked for " + dir.path() + "/dgauss.dat"), std::string::npos) << missing;
    // A copy in a folder next to the scene, named relative to the main scene file's folder, even
    // from an included file in another folder.
    std::ifstream in(test::lensPath("dgauss.dat"), std::ios::binary);
    dir.write("optics/mine.dat", std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
    dir.write("parts/camera.pbrt", "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"optics/mine.dat\"\n");
    const std::string scene = dir.write("main.pbrt", "Include \"parts/camera.pbrt\"\n" + std::string(kWorld));
    const RenderOutput out = test::render(scene, 8, 8, 1);
    EXPECT_EQ(out.metadata.at("lensFile"), (std::filesystem::path(dir.path()) / "optics/mine.dat").string());
}

TEST(CameraGenerations, AZeroShutterIntervalRendersAtUnitExposureWithAWarning) {
    test::TempDir dir;
    const auto scene = [&](const std::string& name, const std::string& shutter) {
        return dir.write(name, test::courseCamera("dgauss.dat", "\"float fstop\" 8 \"float focaldistance\" 3000 " + shutter) +
                                   "\n" + kWorld);
    };
    const std::string zero = scene("zero.pbrt", "\"float shutteropen\" 0 \"float shutterclose\" 0");
    SceneDescription parsed = parseSceneFile(zero);
    makeCamera(parsed, {}, 8, 8, 0);
    ASSERT_EQ(parsed.warnings.size(), 1u);
    EXPECT_NE(parsed.warnings[0].find("zero.pbrt:2: Camera \"realistic\": shutteropen = shutterclose = 0"), std::string::npos)
        << parsed.warnings[0];
    EXPECT_NE(parsed.warnings[0].find("unit exposure"), std::string::npos);
    const Image unit = test::render(scene("unit.pbrt", ""), 24, 24, 4).image;
    const Comparison z = compare(test::render(zero, 24, 24, 4).image, unit);
    EXPECT_GT(z.meanB, 1e-3);
    EXPECT_NEAR(z.meanA / z.meanB, 1.0, 1e-6);
    const Comparison half = compare(test::render(scene("half.pbrt", "\"float shutterclose\" 0.5"), 24, 24, 4).image, unit);
    EXPECT_NEAR(half.meanA / half.meanB, 0.5, 1e-6);
    EXPECT_NE(renderError(scene("back.pbrt", "\"float shutteropen\" 1 \"float shutterclose\" 0.5"))
                  .find("shutterclose (0.5) comes before shutteropen (1)"),
              std::string::npos);
}

TEST(CameraGenerations, TheLaterCoursesClippingPlanesWarnOnlyWhenTheyWouldClip) {
    test::TempDir dir;
    const auto warnings = [&](const std::string& clip) {
        SceneDescription s = parseSceneFile(dir.write("h.pbrt",
            test::courseCamera("dgauss.dat", "\"float fstop\" 8 " + clip) + "\n" + kWorld));
        makeCamera(s, {}, 8, 8, 0);
        return s.warnings;
    };
    EXPECT_TRUE(warnings("\"float hither\" 0.001 \"float yon\" 1e30").empty());
    const std::vector<std::string> w = warnings("\"float hither\" 10 \"float yon\" 1e30");
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("hither 10 / yon 1e+30 not applied"), std::string::npos) << w[0];
}

// Every shape passes as much light as the circle: the weight integrates to pi over the stop.
double throughput(const ApertureShape& shape) {
    const int n = 800;
    double sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) sum += shape.weight(-1 + (2 * i + 1.0) / n, -1 + (2 * j + 1.0) / n);
    return sum * 4.0 / (double(n) * n);
}

TEST(ApertureShapes, NamedShapesHaveTheirOutlinesAndTheCirclesThroughput) {
    for (const char* name : {"circular", "gaussian", "square", "pentagon", "star"})
        EXPECT_NEAR(throughput(ApertureShape::named(name)), M_PI, 0.01) << name;
    const ApertureShape square = ApertureShape::named("square");
    EXPECT_NEAR(square.weight(0.49, -0.49), M_PI, 1e-12);  // pi over its area of 1
    EXPECT_EQ(square.weight(0.51, 0), 0);
    const ApertureShape pentagon = ApertureShape::named("pentagon");  // a corner toward -y, as pbrt-v4's
    EXPECT_GT(pentagon.weight(0, -0.78), 0);
    EXPECT_EQ(pentagon.weight(0, 0.78), 0);
    const ApertureShape star = ApertureShape::named("star");  // points at 36 + 72 k degrees
    const double a = 36 * M_PI / 180;
    EXPECT_GT(star.weight(0.95 * std::cos(a), 0.95 * std::sin(a)), 0);
    EXPECT_EQ(star.weight(0.95, 0), 0);
    EXPECT_EQ(ApertureShape::named("gaussian").weight(0.999, 0) < 0.01, true);
    EXPECT_THROW(ApertureShape::named("hexagon"), std::invalid_argument);
}

TEST(ApertureShapes, AnImageApertureOpensWhereTheImageIsBright) {
    test::TempDir dir;
    Image im;  // white in the top half (+v), black below
    im.width = im.height = 16;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) im.rgb.push_back(y < 8 ? 1.0f : 0.0f);
    const std::vector<std::uint8_t> png = encodePng(im);
    const std::string path = dir.write("half.png", std::string(png.begin(), png.end()));
    const ApertureShape half = ApertureShape::fromImage(path);
    EXPECT_GT(half.weight(0, 0.5), 0);
    EXPECT_EQ(half.weight(0, -0.5), 0);
    // Normalised over the image's square as pbrt-v4 does (mean 1/2: scale pi / 2), over the half disc.
    EXPECT_NEAR(throughput(half), M_PI * M_PI / 4, 0.05);
    EXPECT_THROW(ApertureShape::fromImage(dir.path() + "/none.png"), std::runtime_error);
}

TEST(ApertureShapes, AnyOtherNameIsAnImageFileResolvedFromTheSceneFolder) {
    test::TempDir dir;
    const std::string e = renderError(dir.write("h.pbrt",
        test::courseCamera("dgauss.dat", "\"string aperture\" \"hexagon\"\n") + kWorld));
    EXPECT_NE(e.find("cannot open 'hexagon' (looked for " + dir.path() + "/hexagon)"), std::string::npos) << e;
}

struct Bokeh {
    double fourfold = 0;  // sum I r^4 cos 4 theta / sum I r^4 about the centroid: 0 for a disc, -0.43 for a square
    double twofold = 0;   // sum I r^2 cos 2 theta / sum I r^2: 0 unless stretched along x or y
    double total = 0;     // the spot's summed luminance
};

// A small glowing ball 0.5 m ahead of dgauss.50mm wide open and focused at 100 m: its blur spot (about
// 22 pixels across here) is the stop's shape, widened a little by the ball's own image. Intensity-
// weighted angular moments measure the shape without thresholding the noise. mode: the lens model.
Bokeh bokeh(const std::string& aperture, const std::string& mode = "exact") {
    test::TempDir dir;
    const std::string scene = dir.write("bokeh.pbrt",
        test::courseCamera("dgauss.50mm.dat", "\"float focaldistance\" 100000 \"float filmdiag\" 35 "
                                              "\"string aperture\" \"" + aperture + "\" \"string mode\" \"" + mode + "\"\n") +
        "Film \"image\"\nPixelFilter \"box\"\nWorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1000 1000 1000]\n"
        "Translate 0 0 0.5\nShape \"sphere\" \"float radius\" 0.004\nAttributeEnd\nWorldEnd\n");
    RenderSettings s;
    s.crop = std::array<double, 4>{0.4, 0.6, 0.4, 0.6};
    const Image im = test::render(scene, 256, 256, 128, s).image;
    Bokeh b;
    double cx = 0, cy = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            b.total += test::lum(im, x, y);
            cx += test::lum(im, x, y) * x;
            cy += test::lum(im, x, y) * y;
        }
    cx /= b.total;
    cy /= b.total;
    double r2Sum = 0, r4Sum = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double v = test::lum(im, x, y), dx = x - cx, dy = y - cy, r2 = dx * dx + dy * dy;
            b.twofold += v * (dx * dx - dy * dy);               // r^2 cos 2 theta
            b.fourfold += v * (r2 * r2 - 8 * dx * dx * dy * dy);  // r^4 cos 4 theta
            r2Sum += v * r2;
            r4Sum += v * r2 * r2;
        }
    b.twofold /= r2Sum;
    b.fourfold /= r4Sum;
    return b;
}

TEST(ApertureShapes, ASquareApertureMakesSquareBokehOfTheSameBrightness) {
    const Bokeh circle = bokeh("circular"), square = bokeh("square");
    RecordProperty("circle_fourfold", exactText(circle.fourfold));
    RecordProperty("square_fourfold", exactText(square.fourfold));
    RecordProperty("brightness_ratio", exactText(square.total / circle.total));
    EXPECT_NEAR(circle.fourfold, 0, 0.05);
    EXPECT_LT(square.fourfold, -0.15);  // mass toward the corners (the ball's own image rounds them)
    EXPECT_NEAR(square.twofold, 0, 0.05);
    EXPECT_NEAR(square.total / circle.total, 1.0, 0.05);
    // The thick lens meets the shape at the exit pupil, the stop's image.
    EXPECT_LT(bokeh("square", "thick").fourfold, -0.15);
}

}  // namespace
}  // namespace lenslab
