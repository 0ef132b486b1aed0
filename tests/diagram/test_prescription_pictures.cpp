// Diagrams of real prescriptions, read back as pixels: the F, d and C fans in their colours, an
// asphere drawn along its true profile (not its base sphere), mirrors and a central obscuration.
#include <gtest/gtest.h>

#include <cmath>

#include "DiagramStyle.h"
#include "DiagramTestSupport.h"
#include "LensOutline.h"
#include "prescription/CodeVFile.h"

namespace lenslab::test {
namespace {

using namespace diagram_style;

int pixelsShowing(const RgbaImage& image, Rgba colour) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            count += showsColour(pixelAt(image, {double(x), double(y)}), colour, 0.6);
    return count;
}

LensSystem lensFile(const std::string& relative) { return loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/" + relative); }

}  // namespace

TEST(PrescriptionPictures, ColourFansDrawTheThreeLinesAndOnlyWhenAsked) {
    const LensSystem lens = lensFile("lenses/us2015-0092100-ex1-55mm.zmx");
    DiagramOptions o;
    o.lens.fstop = Setting{2.8, "test"};
    o.colourFans = true;
    const RgbaImage colour = renderDiagram(lens, o);
    // Drawn C, d, F: where the fans coincide F covers the others; they show where the glass spreads
    // them, d (between the two) least.
    EXPECT_GT(pixelsShowing(colour, kLineF), 1000);
    EXPECT_GT(pixelsShowing(colour, kLineC), 15);
    EXPECT_GT(pixelsShowing(colour, kLineD), 15);
    EXPECT_LT(pixelsShowing(colour, kExactRay), 50);  // the legend's colours only, no plain exact rays
    o.colourFans = false;
    const RgbaImage plain = renderDiagram(lens, o);
    EXPECT_GT(pixelsShowing(plain, kExactRay), 1000);
    EXPECT_EQ(pixelsShowing(plain, kLineC), 0);
}

TEST(PrescriptionPictures, AnAsphereIsDrawnAlongItsTrueProfile) {
    // Biconvex lens whose front is a strong even asphere: at 14 mm its sag is 0.6 mm less than its
    // base sphere's, about 9 pixels in this picture.
    LensTable t = parseLensTable("40 6 1.6 30\n-120 2 0 30\n0 30 0 20\n", "asphere.dat", TableLayout::GapAfter);
    t.rows[0].conic = -0.8;
    t.rows[0].aspheric = {0, -2e-5, 3e-8, -1e-11, 0, 0, 0, 0};
    const LensSystem lens = buildLensSystem(t);
    DiagramOptions o;
    o.fieldHeight = 0.0;
    const DiagramPicture picture = layoutDiagram(lens, o);
    const RgbaImage image = renderDiagram(lens, o);
    Surface sphere = lens.surfaces[0];
    sphere.conic = 0;
    sphere.aspheric = {};
    const double h = 14;
    const Point2 onAsphere = picture.view.toPicture({-sag(lens.surfaces[0], h), h});
    const Point2 onSphere = picture.view.toPicture({-sag(sphere, h), h});
    ASSERT_GT(std::fabs(onAsphere.x - onSphere.x), 6);
    EXPECT_TRUE(showsNear(image, onAsphere, kLensLine));
    EXPECT_FALSE(showsNear(image, onSphere, kLensLine));
}

TEST(PrescriptionPictures, MirrorsAndTheObscurationAreDrawn) {
    const LensSystem lens = lensFile("tests/optics/data/cassegrain-obscured.zmx");
    DiagramOptions o;
    const DiagramPicture picture = layoutDiagram(lens, o);
    const RgbaImage image = renderDiagram(lens, o);
    // The primary mirror's arc at half its height, heavy and grey: fully covered pixels of its colour
    // (a thin lens line's anti-aliased edge can pass for it at partial coverage).
    const Surface& primary = lens.surfaces[1];
    ASSERT_TRUE(primary.mirror);
    const double h = 0.5 * primary.apertureRadius;
    EXPECT_TRUE(showsNear(image, picture.view.toPicture({primary.z - sag(primary, h), h}), kMirror, 0.9));
    // The obscuration: a dark bar across the axis on the first surface, 15 mm either side.
    const Surface& window = lens.surfaces[0];
    ASSERT_EQ(window.obscurationRadius, 15);
    for (double y : {-10.0, 10.0}) EXPECT_TRUE(showsNear(image, picture.view.toPicture({window.z, y}), kStop)) << y;
}

// A plate tilted 10 degrees about x (Code V DAR on both faces) is drawn tilted: its flat faces run
// at tan(10 deg) in the (z, y) plane the rays are drawn in, each through its vertex; the singlet
// behind it (the plate's tilt undone: DAR) is drawn as the surfaces' profiles give it.
TEST(PrescriptionPictures, ATiltedPlateIsDrawnTilted) {
    const std::string text = "rdm\nso 0 1e10\ns 0 4 n-bk7_schott\ndar\nade 10\ns 0 5\ndar\nade 10\n"
                             "s 50 5 n-bk7_schott\nsto\ns -50 45\nsi 0 0\nepd 10; wl 587.5618\n";
    const LensSystem lens = buildLensSystem(parseCodeV(text, "plate.seq"));
    const LensOutline outline = buildLensOutline(lens);
    ASSERT_EQ(outline.glass.size(), 2u);
    const GlassElement& plate = outline.glass[0];
    const double slope = std::tan(10 * M_PI / 180);
    for (const auto* face : {&plate.front, &plate.rear}) {
        const double vertexZ = face == &plate.front ? lens.surfaces[0].z : lens.surfaces[1].z;
        for (const ZY& p : *face) EXPECT_NEAR(std::fabs(p.z - vertexZ), slope * std::fabs(p.y), 1e-9) << p.y;
        EXPECT_GT(std::fabs(face->front().z - face->back().z), 1.0);  // tilted indeed: 2 mm over the plate
    }
    const GlassElement& singlet = outline.glass[1];
    for (std::size_t k = 0; k < singlet.front.size(); ++k) {
        EXPECT_NEAR(singlet.front[k].z, profileZ(lens.surfaces[2], singlet.front[k].y), 1e-12);
        EXPECT_NEAR(singlet.rear[k].z, profileZ(lens.surfaces[3], singlet.rear[k].y), 1e-12);
    }
}

}  // namespace lenslab::test
