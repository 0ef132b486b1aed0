// The Zemax .zmx reader: every field in its place and unit, the encodings, the dispatch by
// content, and every refusal with its file:line. The files in data/ are the project's own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"
#include "prescription/ZemaxFile.h"
#include "settings/LensAnalysis.h"
#include "Utf16.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;
using lenslab::test::toUtf16;

namespace {

std::string dataPath(const std::string& file) { return std::string(LENSLAB_SOURCE_DIR) + "/tests/optics/data/" + file; }

std::string readBytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    EXPECT_TRUE(f) << path;
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

LensTable readData(const std::string& file) { return readLensTable(dataPath(file)); }

void expectSameRows(const LensTable& a, const LensTable& b, double tolerance) {
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        EXPECT_NEAR(a.rows[i].radius, b.rows[i].radius, tolerance) << "row " << i;
        EXPECT_NEAR(a.rows[i].gap, b.rows[i].gap, tolerance) << "row " << i;
        EXPECT_NEAR(a.rows[i].diameter, b.rows[i].diameter, tolerance) << "row " << i;
        EXPECT_EQ(a.rows[i].index, b.rows[i].index) << "row " << i;
        EXPECT_EQ(a.rows[i].abbe, b.rows[i].abbe) << "row " << i;
        EXPECT_EQ(a.rows[i].stop, b.rows[i].stop) << "row " << i;
    }
}

// A singlet with one line of the header (line 2) and one line of SURF 1 (line 13) to vary.
std::string zmxSinglet(const std::string& surfaceLine = "  CONI 0", const std::string& headerLine = "MODE SEQ") {
    return "VERS 140124\n" + headerLine + "\nUNIT MM\n"  // 1-3
           "SURF 0\n  CURV 0\n  DISZ INFINITY\n"         // 4-6
           "SURF 1\n  STOP\n  CURV 0.02\n  DISZ 5\n  GLAS N-BK7 0 0 1.5168 64.17\n  DIAM 10\n" +  // 7-12
           surfaceLine + "\n"                                                                    // 13
           "SURF 2\n  CURV -0.02\n  DISZ 40\n  DIAM 10\n"                                        // 14-17
           "SURF 3\n  CURV 0\n  DISZ 0\n";                                                       // 18-20
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

void expectZemaxError(const std::string& bytes, int line, const std::string& part) {
    expectReadError([&] { parseZemax(bytes, "bad.zmx"); }, bytes, "bad.zmx", line, part);
}

}  // namespace

TEST(Zemax, DoubleGaussRowsEqualTheLensTable) {
    const LensTable dat = readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    const LensTable zmx = readData("dgauss.50mm.zmx");
    EXPECT_EQ(zmx.format, "zmx");
    EXPECT_EQ(zmx.layout, TableLayout::GapAfter);
    EXPECT_TRUE(zmx.layoutDetected);
    ASSERT_EQ(zmx.rows.size(), dat.rows.size());
    for (std::size_t i = 0; i < dat.rows.size(); ++i) {
        const LensTableRow &d = dat.rows[i], &z = zmx.rows[i];
        EXPECT_NEAR(z.radius, d.radius, 1e-9) << "row " << i;
        if (i + 1 < dat.rows.size()) {
            EXPECT_NEAR(z.gap, d.gap, 1e-12) << "row " << i;
        }
        EXPECT_EQ(z.index, d.index == 1 ? 0 : d.index) << "row " << i;  // the table writes air as 1
        EXPECT_NEAR(z.diameter, d.diameter, 1e-12) << "row " << i;      // DIAM is half of it
        EXPECT_EQ(z.stop, d.stop) << "row " << i;
    }
    // The table's last gap is 0 (the film is placed later); the .zmx keeps the design's image distance.
    EXPECT_DOUBLE_EQ(zmx.rows.back().gap, 36.1059);
}

TEST(Zemax, DoubleGaussHeaderFields) {
    const LensTable t = readData("dgauss.50mm.zmx");
    ASSERT_EQ(t.comments.size(), 3u);
    EXPECT_EQ(t.comments[0], "Double Gauss 50 mm \xc6\x92/2 \xe2\x80\x94 \xc3\x98 25.2 mm");  // NAME first
    EXPECT_EQ(t.comments[1], "lenslab test file: lenses/dgauss.50mm.dat written as a Zemax prescription.");
    // Zemax lists 24 wavelength slots; the unused ones (0.55 um, weight 1) after the last used are dropped.
    ASSERT_EQ(t.wavelengths.size(), 3u);
    EXPECT_NEAR(t.wavelengths[0], 486.1327, 1e-9);  // micrometres in the file, nm here
    EXPECT_NEAR(t.wavelengths[2], 656.2725, 1e-9);
    EXPECT_NEAR(t.primaryWavelength, 587.5618, 1e-9);  // PWAV 2
    EXPECT_EQ(t.catalogs, (std::vector<std::string>{"SCHOTT", "OHARA"}));
    ASSERT_TRUE(t.entrancePupilDiameter);
    EXPECT_NEAR(*t.entrancePupilDiameter, 25, 1e-12);
    EXPECT_FALSE(t.designFNumber);
    // Model glasses: nd and Vd from the GLAS line, no catalog name; the line is the SURF's.
    EXPECT_EQ(t.rows[0].glass, "");
    EXPECT_DOUBLE_EQ(t.rows[0].abbe, 47.2);
    EXPECT_EQ(t.rows[1].abbe, 0);
    EXPECT_FALSE(t.rows[0].mirror);
    const std::string text = readBytes(dataPath("dgauss.50mm.zmx"));
    int surf1Line = 1;
    for (std::size_t i = 0; i < text.find("SURF 1\r\n"); ++i) surf1Line += text[i] == '\n';
    EXPECT_EQ(t.rows[0].line, surf1Line);
}

TEST(Zemax, InchesReadAsTheSameMillimetres) {
    const LensTable mm = readData("dgauss.50mm.zmx");
    const LensTable in = readData("dgauss.50mm.inches.zmx");
    expectSameRows(mm, in, 1e-9);
    EXPECT_NEAR(mm.rows.back().gap, in.rows.back().gap, 1e-9);
    EXPECT_NEAR(*in.entrancePupilDiameter, 25, 1e-9);
}

TEST(Zemax, Utf16WithByteOrderMarkReadsAsUtf8) {
    const std::string utf8 = readBytes(dataPath("dgauss.50mm.zmx"));
    const LensTable a = parseZemax(utf8, "a.zmx");
    for (bool littleEndian : {true, false}) {
        const std::string utf16 = toUtf16(utf8, littleEndian);
        EXPECT_TRUE(looksLikeZemax(utf16));
        const LensTable b = parseLensTable(utf16, "b.zmx");  // dispatched by content
        EXPECT_EQ(b.format, "zmx");
        expectSameRows(a, b, 0);
        EXPECT_EQ(a.comments, b.comments);  // non-ASCII NAME, and a NOTE beyond the BMP (surrogates)
        for (std::size_t i = 0; i < a.rows.size(); ++i) EXPECT_EQ(a.rows[i].line, b.rows[i].line);
    }
    // A UTF-8 byte order mark is skipped too.
    expectSameRows(a, parseLensTable("\xef\xbb\xbf" + utf8, "c.zmx"), 0);
}

TEST(Zemax, EvenAsphereSinglet) {
    const LensTable t = readData("evenasph-singlet.zmx");
    ASSERT_EQ(t.rows.size(), 2u);
    const LensTableRow& a = t.rows[0];
    EXPECT_DOUBLE_EQ(a.radius, 25);
    EXPECT_DOUBLE_EQ(a.gap, 6);
    EXPECT_DOUBLE_EQ(a.conic, -0.6);
    const AsphericCoefficients expected = {1.0e-4, -2.5e-6, 3.0e-9, -4.0e-12, 5.0e-15, -6.0e-18, 7.0e-21, -8.0e-24};
    for (int i = 0; i < kAsphericTerms; ++i) EXPECT_DOUBLE_EQ(a.aspheric[i], expected[i]) << "PARM " << i + 1;
    // A catalog glass: the name, and nd from the GLAS line; its Vd is the catalog's business.
    EXPECT_EQ(a.glass, "N-BK7");
    EXPECT_DOUBLE_EQ(a.index, 1.5168);
    EXPECT_EQ(a.abbe, 0);
    EXPECT_DOUBLE_EQ(a.diameter, 20);
    EXPECT_TRUE(a.stop);
    const LensTableRow& b = t.rows[1];
    EXPECT_DOUBLE_EQ(b.radius, -200);
    EXPECT_DOUBLE_EQ(b.diameter, 18);  // CLAP's 9 overrides DIAM 9.5 (and MEMA 11)
    EXPECT_EQ(b.index, 0);
    EXPECT_EQ(b.aspheric, AsphericCoefficients{});
    EXPECT_FALSE(b.stop);
    EXPECT_EQ(*t.designFNumber, 2.5);
    ASSERT_EQ(t.wavelengths.size(), 1u);
    EXPECT_NEAR(t.wavelengths[0], 587.5618, 1e-9);
}

TEST(Zemax, ModelGlassesInCentimetres) {
    const LensTable t = readData("model-doublet.cm.zmx");
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_DOUBLE_EQ(t.rows[0].radius, 62.5);  // CURV 0.16 per cm
    EXPECT_DOUBLE_EQ(t.rows[0].gap, 6);
    EXPECT_DOUBLE_EQ(t.rows[0].diameter, 26);
    EXPECT_DOUBLE_EQ(t.rows[0].index, 1.5168);  // ___BLANK: a model glass
    EXPECT_DOUBLE_EQ(t.rows[0].abbe, 64.17);
    EXPECT_EQ(t.rows[0].glass, "");
    EXPECT_NEAR(t.rows[1].radius, -1000.0 / 24, 1e-12);
    EXPECT_DOUBLE_EQ(t.rows[1].index, 1.6477);  // solve flag 1: a model glass whatever its name
    EXPECT_DOUBLE_EQ(t.rows[1].abbe, 33.85);
    EXPECT_EQ(t.rows[1].glass, "");
    EXPECT_DOUBLE_EQ(t.rows[2].diameter, 27);  // DIAM 0: the mechanical semi-diameter stands in
    EXPECT_DOUBLE_EQ(t.rows[2].gap, 95);
    EXPECT_EQ(t.rows[2].index, 0);
    EXPECT_DOUBLE_EQ(*t.entrancePupilDiameter, 25);
    EXPECT_TRUE(t.wavelengths.empty());
    EXPECT_EQ(t.primaryWavelength, kWavelengthD);  // no WAVM: the d line
}

TEST(Zemax, MirrorsAndObscuration) {
    const LensTable t = readData("cassegrain-obscured.zmx");
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_DOUBLE_EQ(t.rows[0].obscurationDiameter, 30);  // OBSC 0 15: radius 15
    EXPECT_DOUBLE_EQ(t.rows[0].diameter, 100);
    EXPECT_FALSE(t.rows[0].mirror);
    EXPECT_TRUE(t.rows[1].mirror);
    EXPECT_TRUE(t.rows[1].stop);
    EXPECT_DOUBLE_EQ(t.rows[1].radius, -400);
    EXPECT_DOUBLE_EQ(t.rows[1].conic, -1);
    EXPECT_DOUBLE_EQ(t.rows[1].gap, -150);  // back toward the object after the mirror
    EXPECT_EQ(t.rows[1].index, 0);          // a mirror in air leaves the ray in air
    EXPECT_EQ(t.rows[1].glass, "");
    EXPECT_TRUE(t.rows[2].mirror);
    EXPECT_DOUBLE_EQ(t.rows[2].gap, 200);
    EXPECT_DOUBLE_EQ(t.rows[2].conic, -3.5);
}

TEST(Zemax, ManginMirrorKeepsTheGlassItReflectsIn) {
    const std::string text = replaced(zmxSinglet(), "SURF 2\n  CURV -0.02\n  DISZ 40\n",
                                      "SURF 2\n  CURV -0.02\n  DISZ -5\n  GLAS MIRROR 0 0 1.5 40\n");
    const LensTable t = parseZemax(replaced(text, "SURF 3\n  CURV 0\n  DISZ 0\n",
                                            "SURF 3\n  CURV 0.02\n  DISZ -30\n  DIAM 10\nSURF 4\n  CURV 0\n  DISZ 0\n"),
                                   "mangin.zmx");
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_TRUE(t.rows[1].mirror);
    EXPECT_EQ(t.rows[1].glass, "N-BK7");
    EXPECT_DOUBLE_EQ(t.rows[1].index, 1.5168);
    EXPECT_EQ(t.rows[2].index, 0);
    EXPECT_DOUBLE_EQ(t.rows[2].gap, -30);
}

// COAT: a material's name as Zemax spells it, a stack in lenslab's text; a blank one says nothing.
TEST(Zemax, CoatingsAreReadFromCoat) {
    const LensTable t = parseZemax(replaced(zmxSinglet("  COAT MGF2"), "  DISZ 40\n", "  DISZ 40\n  COAT MgF2+ZrO2:2q@500\n"),
                                   "coated.zmx");
    EXPECT_EQ(t.rows[0].coating, "MGF2");
    EXPECT_EQ(t.rows[1].coating, "MgF2+ZrO2:2q@500");
    EXPECT_EQ(parseZemax(zmxSinglet("  COAT"), "blank.zmx").rows[0].coating, "");
}

// A vendor's coating defined only in a COATING.DAT file (Thorlabs' THORC): the lens reads, the
// surface keeps the default coating, and a warning names the line and the coating.
TEST(Zemax, CoatingDefinedOnlyInACoatingFileIsWarnedAbout) {
    const LensTable t = parseZemax(zmxSinglet("  COAT THORC"), "thorlabs.zmx");
    EXPECT_EQ(t.rows[0].coating, "");
    ASSERT_EQ(t.warnings.size(), 1u);
    EXPECT_EQ(t.warnings[0].line, 13);
    EXPECT_NE(t.warnings[0].message.find("coating THORC"), std::string::npos) << t.warnings[0].message;
    EXPECT_NE(t.warnings[0].message.find("COATING.DAT"), std::string::npos) << t.warnings[0].message;
}

TEST(ZemaxErrors, CoatingOnAMirror) {
    const std::string text = replaced(zmxSinglet(), "SURF 2\n  CURV -0.02\n  DISZ 40\n",
                                      "SURF 2\n  CURV -0.02\n  DISZ -5\n  GLAS MIRROR 0 0 1.5 40\n  COAT MGF2\n");
    const std::string lens = replaced(text, "SURF 3\n  CURV 0\n  DISZ 0\n",
                                      "SURF 3\n  CURV 0.02\n  DISZ -30\n  DIAM 10\nSURF 4\n  CURV 0\n  DISZ 0\n");
    try {
        buildLensSystem(parseZemax(lens, "bad.zmx"));
        FAIL() << "a coated mirror was accepted";
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 14);
        EXPECT_NE(e.problem().find("on a mirror"), std::string::npos) << e.what();
    }
}

TEST(Zemax, AsphericTermsScaleAsLengthToOneMinusTwoI) {
    std::string text = replaced(zmxSinglet("  PARM 1 2\n  PARM 2 3\n  PARM 8 5"), "UNIT MM", "UNIT IN");
    text = replaced(text, "  STOP\n", "  STOP\n  TYPE EVENASPH\n");
    const LensTable t = parseZemax(text, "in.zmx");
    const double in = 25.4;
    EXPECT_NEAR(t.rows[0].aspheric[0], 2 / in, 1e-15);               // r^2: length^-1
    EXPECT_NEAR(t.rows[0].aspheric[1] / (3 / std::pow(in, 3)), 1, 1e-14);   // r^4: length^-3
    EXPECT_NEAR(t.rows[0].aspheric[7] / (5 / std::pow(in, 15)), 1, 1e-14);  // r^16: length^-15
    EXPECT_DOUBLE_EQ(t.rows[0].radius, 50 * in);
    EXPECT_DOUBLE_EQ(t.rows[0].gap, 5 * in);
    EXPECT_DOUBLE_EQ(t.rows[0].diameter, 20 * in);
    const LensTable m = parseZemax(replaced(zmxSinglet(), "UNIT MM", "UNIT M X W"), "m.zmx");
    EXPECT_DOUBLE_EQ(m.rows[1].gap, 40000);
    // A STANDARD surface has no parameters: stale PARM lines do not make it aspheric.
    EXPECT_EQ(parseZemax(zmxSinglet("  PARM 2 3"), "std.zmx").rows[0].aspheric, AsphericCoefficients{});
}

TEST(Zemax, SurfaceWithoutTypeIsStandardAndIgnoredLinesAreIgnored) {
    const LensTable t = parseZemax(zmxSinglet("  FIMP \n  HIDE 0 0 0\n  MIRR 2 0\n  SLAB 3\n  POPS 0 0 1\n  COMM x\n  DECX 0\n  TILT 0"
                                           "\n  SCBD 1 0 0 0 0 0\n  OBDC 0 0"),
                                   "ok.zmx");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[1].line, 23);
}

TEST(Zemax, DispatchIsByContentNotByName) {
    EXPECT_TRUE(looksLikeZemax(readBytes(dataPath("dgauss.50mm.zmx"))));
    EXPECT_TRUE(looksLikeZemax("\n\n  SURF 0\n"));
    EXPECT_FALSE(looksLikeZemax(readBytes(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat")));
    EXPECT_FALSE(looksLikeZemax("50 0 1.5 20\n"));
    EXPECT_FALSE(looksLikeZemax(""));
    // A .zmx saved under a .dat name is still read as Zemax.
    const std::string path = testing::TempDir() + "lenslab-zemax-as.dat";
    std::ofstream(path, std::ios::binary) << readBytes(dataPath("evenasph-singlet.zmx"));
    EXPECT_EQ(readLensTable(path).format, "zmx");
    EXPECT_EQ(readLensTable(path, TableLayout::GapAfter).layoutDetected, false);
    std::remove(path.c_str());
    EXPECT_EQ(parseLensTable("50 0 1.5 20\n0 5 0 10\n", "t.dat").format, "table");
}

// A folded, decentred, shaped file: coordinate breaks as rows of their own, the surface forms, shaped
// and decentred apertures, the file's fields, wavelength weights and surface comments.
TEST(Zemax, CoordinateBreaksFormsAperturesAndFields) {
    const std::string text =
        "VERS 1\nMODE SEQ\nUNIT CM\n"                                               // 1-3
        "FTYP 1 0 2 2 0 0 0\nXFLN 0 0.5 0 0\nYFLN 0 1.5 0 0\nFWGN 1 2 1 1\nOBNA 0.1 0\n"  // 4-8
        "WAVM 1 0.5 2\nWAVM 2 0.6 1\nWAVM 3 0.55 1\nPWAV 1\n"                       // 9-12
        "SURF 0\n  CURV 0\n  DISZ 30\n"                                             // 13-15
        "SURF 1\n  STOP\n  TYPE ODDASPH\n  COMM front\n  CURV 0.02\n  PARM 1 0.001\n  PARM 3 -2e-5\n"  // 16-22
        "  DISZ 0.5\n  GLAS N-BK7 0 0 1.5168 64.17\n  DIAM 1\n"                    // 23-25
        "SURF 2\n  TYPE COORDBRK\n  CURV 0\n  PARM 1 0.1\n  PARM 2 -0.2\n  PARM 3 10\n  PARM 6 1\n  DISZ 0\n"  // 26-33
        "SURF 3\n  TYPE QED_TYPE\n  CURV -0.01\n  CONI -0.5\n  XDAT 1 0\n  XDAT 2 2\n  XDAT 3 1.2\n"  // 34-40
        "  XDAT 4 0.01\n  XDAT 5 -0.002\n  DISZ 4\n  DIAM 1\n  SQAP 0.8 0.5 0\n  OBDC 0.1 0.2\n"  // 41-46
        "SURF 4\n  TYPE TOROIDAL\n  CURV 0.001\n  PARM 1 50\n  DISZ 2\n  DIAM 1\n  ELOB 0.2 0.1\n"  // 47-53
        "SURF 5\n  CURV 0\n  DISZ 0\n";
    const LensTable t = parseZemax(text, "folded.zmx");
    ASSERT_EQ(t.rows.size(), 4u);
    const LensTableRow &odd = t.rows[0], &cb = t.rows[1], &q = t.rows[2], &toroid = t.rows[3];
    EXPECT_EQ(odd.name, "front");
    EXPECT_EQ(odd.form.kind, SurfaceKind::OddAsphere);
    EXPECT_NEAR(odd.form.terms[0], 0.001, 1e-18);                 // r^1: dimensionless
    EXPECT_NEAR(odd.form.terms[2], -2e-5 / 100, 1e-20);           // r^3: cm^-2 -> mm^-2
    EXPECT_EQ(odd.form.termCount, 3);
    EXPECT_TRUE(cb.coordinateBreak);
    ASSERT_TRUE(cb.frame);
    EXPECT_EQ(cb.frame->decentre, (std::array<double, 3>{1, -2, 0}));  // cm -> mm
    EXPECT_EQ(cb.frame->tiltDegrees, (std::array<double, 3>{10, 0, 0}));
    EXPECT_EQ(cb.frame->order, TiltOrder::TiltThenDecentre);
    EXPECT_EQ(cb.glass, "N-BK7");  // a coordinate break leaves the medium as it was
    EXPECT_EQ(q.form.kind, SurfaceKind::Qcon);
    EXPECT_DOUBLE_EQ(q.form.normalisationRadius, 12);
    EXPECT_EQ(q.form.termCount, 2);
    EXPECT_DOUBLE_EQ(q.form.terms[1], -0.02);
    ASSERT_TRUE(q.clearShape);
    EXPECT_EQ(q.clearShape->kind, ApertureKind::Rectangular);
    EXPECT_DOUBLE_EQ(q.clearShape->halfWidthY, 5);
    EXPECT_DOUBLE_EQ(q.clearShape->centreY, 2);
    EXPECT_EQ(toroid.form.kind, SurfaceKind::Toroidal);
    EXPECT_DOUBLE_EQ(toroid.form.terms[0], 500);
    ASSERT_TRUE(toroid.obscurationShape);
    EXPECT_EQ(toroid.obscurationShape->kind, ApertureKind::Elliptical);
    EXPECT_EQ(t.fields.type, FieldType::ObjectHeight);
    ASSERT_EQ(t.fields.points.size(), 2u);  // FTYP's count
    EXPECT_DOUBLE_EQ(t.fields.points[1].x, 5);
    EXPECT_DOUBLE_EQ(t.fields.points[1].y, 15);
    EXPECT_DOUBLE_EQ(t.fields.points[1].weight, 2);
    EXPECT_EQ(t.wavelengths, (std::vector<double>{500, 600}));  // FTYP's wavelength count
    EXPECT_EQ(t.wavelengthWeights, (std::vector<double>{2, 1}));
    EXPECT_DOUBLE_EQ(*t.objectNumericalAperture, 0.1);
    EXPECT_DOUBLE_EQ(t.objectDistance, 300);
    const LensSystem lens = buildLensSystem(t);
    ASSERT_EQ(lens.surfaces.size(), 3u);  // the coordinate break is no surface
    EXPECT_TRUE(lens.decentred);
    EXPECT_FALSE(lens.surfaces[1].before.isIdentity());
}

TEST(ZemaxErrors, GapBeforeLayoutDoesNotApply) {
    try {
        parseLensTable(zmxSinglet(), "x.zmx", TableLayout::GapBefore);
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_NE(e.problem().find("gap-before layout does not apply"), std::string::npos) << e.what();
    }
}

TEST(ZemaxErrors, CoordinateBreakAsTheStop) { expectZemaxError(zmxSinglet("  TYPE COORDBRK"), 8, "a coordinate break cannot be the stop"); }
// DIAM 0 leaves the clear aperture to the program (Zemax's automatic solve), as a Code V surface
// without CIR; no DIAM at all is still an error (NoSemiDiameter).
TEST(Zemax, DiamZeroIsAnAutomaticClearAperture) {
    const LensTable t = parseZemax(replaced(zmxSinglet(), "  DIAM 10\nSURF 3", "  DIAM 0\nSURF 3"), "auto.zmx");
    EXPECT_TRUE(t.rows[1].automaticDiameter);
    EXPECT_EQ(t.rows[1].diameter, 0);
    EXPECT_FALSE(t.rows[0].automaticDiameter);
}

// WAVM in micrometres reads as exactly the double the same digits in nanometres are: 0.40012 um is
// 400.12 nm, which 0.40012 * 1000 in doubles is not.
TEST(Zemax, WavelengthsInMicrometresAreExactNanometres) {
    ASSERT_NE(0.40012 * 1000, 400.12);
    const LensTable t = parseZemax(zmxSinglet("  CONI 0", "MODE SEQ\nWAVM 1 0.40012 1\nWAVM 2 5.875618E-1 1"), "w.zmx");
    ASSERT_EQ(t.wavelengths.size(), 2u);
    EXPECT_EQ(t.wavelengths[0], 400.12);
    EXPECT_EQ(t.wavelengths[1], 587.5618);
}

TEST(ZemaxErrors, OldFormDecenter) { expectZemaxError(zmxSinglet("  DECY 0.5"), 13, "tilts and decenters in the old form (DECY)"); }
TEST(ZemaxErrors, OldFormTilt) { expectZemaxError(zmxSinglet("  TILT 3"), 13, "tilts and decenters in the old form (TILT)"); }
TEST(ZemaxErrors, SurfaceTiltAfterTheSurface) {
    expectZemaxError(zmxSinglet("  SCBD 2 0 0 0 0 90 0 0"), 13, "only the before-surface tilt and decentre (SCBD 1)");
}
TEST(ZemaxErrors, GradientIndexType) { expectZemaxError(zmxSinglet("  TYPE GRINSUR1"), 13, "gradient-index surfaces (TYPE GRINSUR1)"); }
TEST(ZemaxErrors, GradientIndexLine) { expectZemaxError(zmxSinglet("  GRIN 1 2 3"), 13, "gradient-index media (GRIN)"); }
TEST(ZemaxErrors, OtherTypeIsNamedWithWhatIsSupported) {
    expectZemaxError(zmxSinglet("  TYPE SZERNSAG"), 13, "surface type SZERNSAG is not supported; lenslab reads sequential "
                                                "systems of STANDARD, EVENASPH, ODDASPH, QTYPE/QED_TYPE, TOROIDAL and "
                                                "COORDBRK surfaces");
}
TEST(ZemaxErrors, QTypeKind) { expectZemaxError(zmxSinglet("  TYPE QED_TYPE\n  XDAT 1 2"), 7, "XDAT 1 must be 0 (Qcon) or 1 (Qbfs)"); }
TEST(ZemaxErrors, QTypeTermCount) {
    expectZemaxError(zmxSinglet("  TYPE QED_TYPE\n  XDAT 2 1e12"), 7, "XDAT 2 counts its terms: a whole number up to");
    expectZemaxError(zmxSinglet("  TYPE QED_TYPE\n  XDAT 2 -1"), 7, "XDAT 2 counts its terms");
}
TEST(ZemaxErrors, ToroidExtraTerms) {
    expectZemaxError(zmxSinglet("  TYPE TOROIDAL\n  XDAT 1 3e12"), 14, "extra polynomial terms (XDAT 1 3e+12)");
}
TEST(ZemaxErrors, RectangularApertureSizes) { expectZemaxError(zmxSinglet("  SQAP 4 0 0"), 13, "SQAP needs two positive half widths"); }
TEST(ZemaxErrors, AnnularObscuration) { expectZemaxError(zmxSinglet("  OBSC 1 2 0"), 13, "annular obscurations"); }
TEST(ZemaxErrors, ObscurationCoveringTheAperture) { expectZemaxError(zmxSinglet("  OBSC 0 10 0"), 7, "covers the whole clear aperture"); }
TEST(ZemaxErrors, NonSequential) { expectZemaxError(zmxSinglet("  CONI 0", "MODE NSC"), 2, "only sequential files (MODE SEQ)"); }
TEST(ZemaxErrors, UnknownUnit) { expectZemaxError(replaced(zmxSinglet(), "UNIT MM", "UNIT FT"), 3, "UNIT FT is not one of MM, CM, IN, M"); }
TEST(ZemaxErrors, SurfaceWithoutCurv) { expectZemaxError(replaced(zmxSinglet(), "  CURV -0.02\n", ""), 14, "SURF 2 has no CURV"); }
TEST(ZemaxErrors, NotANumber) { expectZemaxError(zmxSinglet("  CONI abc"), 13, "CONI value 1 is not a finite number: 'abc'"); }
TEST(ZemaxErrors, NotFinite) {
    expectZemaxError(zmxSinglet("  CONI nan"), 13, "not a finite number");
    expectZemaxError(zmxSinglet("  CONI 1e999"), 13, "not a finite number");
    expectZemaxError(replaced(zmxSinglet(), "DISZ 40", "DISZ INFINITY"), 16, "INFINITY only on the object surface");
    expectZemaxError(replaced(zmxSinglet(), "SURF 2\n  CURV -0.02\n  DISZ 40", "SURF 2\n  TYPE COORDBRK\n  CURV 0\n  DISZ INFINITY"), 17,
                "INFINITY only on the object surface");  // a coordinate break's thickness too
    expectZemaxError(replaced(zmxSinglet(), "CURV 0.02", "CURV 1e-320"), 9, "the radius is not a finite number");
    expectZemaxError(replaced(replaced(zmxSinglet(), "UNIT MM", "UNIT M"), "DISZ 40", "DISZ 1e306"), 16,
                "DISZ must be a finite thickness");  // finite in metres, not in millimetres
}
TEST(ZemaxErrors, Empty) {
    expectZemaxError("", 1, "empty file");
    expectZemaxError("\r\n  \r\n", 1, "empty file");
}
TEST(ZemaxErrors, NoLensSurfaces) { expectZemaxError("VERS 1\nSURF 0\n  CURV 0\nSURF 1\n  CURV 0\n", 5, "no lens surfaces"); }
TEST(ZemaxErrors, TwoStops) { expectZemaxError(zmxSinglet("  STOP"), 13, "a second STOP; the first is on line 8"); }
TEST(ZemaxErrors, NoStop) { expectZemaxError(replaced(zmxSinglet(), "  STOP\n", ""), 4, "no STOP"); }
TEST(ZemaxErrors, StopOnTheObject) {
    expectZemaxError(replaced(replaced(zmxSinglet(), "  STOP\n", ""), "SURF 0\n", "SURF 0\n  STOP\n"), 5,
                "the object surface (SURF 0) cannot be the stop");
}
TEST(ZemaxErrors, SurfacesOutOfOrder) { expectZemaxError(replaced(zmxSinglet(), "SURF 2", "SURF 5"), 14, "SURF 5 out of order: expected SURF 2"); }
TEST(ZemaxErrors, NegativeThicknessWithoutMirror) { expectZemaxError(replaced(zmxSinglet(), "DISZ 40", "DISZ -40"), 16, "allowed only after a mirror"); }
TEST(ZemaxErrors, NoSemiDiameter) { expectZemaxError(replaced(zmxSinglet(), "  DIAM 10\nSURF 3", "SURF 3"), 14, "SURF 2 has no positive semi-diameter"); }
TEST(ZemaxErrors, ModelGlassWithoutAbbeNumber) { expectZemaxError(zmxSinglet("  GLAS ___BLANK 1 0 1.5"), 13, "a model glass needs nd >= 1 and Vd >= 0"); }
TEST(ZemaxErrors, IndexBelowOne) { expectZemaxError(zmxSinglet("  GLAS F2 0 0 0.5 30"), 13, "nd 0.5 is below 1"); }
TEST(ZemaxErrors, PrimaryWavelengthMissing) { expectZemaxError(zmxSinglet("  CONI 0", "WAVM 1 0.55 1\nPWAV 3"), 3, "PWAV 3 names no WAVM wavelength (1..1)"); }
// The wavelengths a file lists are ones lenslab traces (180-2500 nm, where glass data reach), the
// primary above all: WAVM 1 0.1 used to give a lens at 100 nm (EFL 6.28 mm), and 1e300 um a
// wavelength_nm of 1e+303.
TEST(ZemaxErrors, WavelengthsOutsideTheTracedRange) {
    expectZemaxError(zmxSinglet("  CONI 0", "WAVM 1 0.1 1"), 2, "WAVM: wavelength 100 nm lies outside 180-2500 nm");
    expectZemaxError(zmxSinglet("  CONI 0", "WAVM 1 1e300 1"), 2, "wavelength 1e+303 nm lies outside");
    expectZemaxError(zmxSinglet("  CONI 0", "WAVM 1 5e-99999999999999999999 1"), 2, "wavelength 0 nm lies outside");
    expectZemaxError(zmxSinglet("  CONI 0", "WAVM 1 0.5876 1\nWAVM 2 -0.5 1\nPWAV 1"), 3, "wavelength -500 nm");
    expectZemaxError(zmxSinglet("  CONI 0", "WAVM 1 0.5876 1\nWAVM 2 10.6 1\nPWAV 1"), 3, "wavelength 10600 nm");
    EXPECT_NEAR(parseZemax(zmxSinglet("  CONI 0", "WAVM 1 0.18 1\nWAVM 2 2.5 1\nPWAV 2"), "ends.zmx").primaryWavelength, 2500, 1e-9);
}
// A telecom lens at 1550 nm and a lithography lens at 248 nm read: N-BK7 at 1550 nm is Schott's
// Sellmeier formula there (written out below, independent of the catalog), and the singlet's EFL is
// the thick-lens formula's with that index. Where a glass's data do not reach a listed wavelength
// the lens reads with a warning: N-BK7 (Schott's data: 300-2500 nm) at 248 nm, a model glass
// (nd and Vd describe the visible) at 1550 nm; N-BK7 at 1550 nm draws none.
TEST(ZemaxWavelengths, InfraredAndUltravioletLensesReadWarningWhereGlassDataEnd) {
    const double l2 = 1.55 * 1.55;
    const double nBk7 = std::sqrt(1 + 1.03961212 * l2 / (l2 - 0.00600069867) + 0.231792344 * l2 / (l2 - 0.0200179144) +
                                  1.01046945 * l2 / (l2 - 103.560653));
    const LensSystem ir = buildLensSystem(parseZemax(zmxSinglet("  CONI 0", "WAVM 1 1.55 1\nPWAV 1"), "ir.zmx"));
    EXPECT_DOUBLE_EQ(ir.primaryWavelength, 1550);
    EXPECT_NEAR(ir.surfaces[0].mediumAfter.nd, 1.5168, 1e-12);
    EXPECT_NEAR(refractiveIndex(ir.surfaces[0].mediumAfter, 1550), nBk7, 1e-12);
    EXPECT_NEAR(nBk7, 1.50066, 1e-5);  // Schott's data sheet: 1.50066 at 1550 nm
    const double r = 50, d = 5, power = (nBk7 - 1) * (2 / r - (nBk7 - 1) * d / (nBk7 * r * r));  // R1 = r, R2 = -r
    EXPECT_NEAR(analyzeLens(ir, LensSettings{}).firstOrder.efl, 1 / power, 1e-9);
    EXPECT_TRUE(ir.warnings.empty()) << ir.warnings.front().message;

    const LensSystem uv = buildLensSystem(parseZemax(zmxSinglet("  CONI 0", "WAVM 1 0.248 1\nPWAV 1"), "uv.zmx"));
    ASSERT_EQ(uv.warnings.size(), 1u);
    EXPECT_EQ(uv.warnings[0].line, uv.surfaces[0].line);  // the glass's surface
    EXPECT_EQ(uv.warnings[0].message.rfind("N-BK7 (SCHOTT)'s data cover 300-2500 nm: its index is extrapolated to 248 nm (n 1.5", 0), 0u)
        << uv.warnings[0].message;

    const LensSystem model = buildLensSystem(parseZemax(
        replaced(zmxSinglet("  CONI 0", "WAVM 1 1.55 1\nWAVM 2 0.5876 1\nPWAV 2"), "GLAS N-BK7 0 0", "GLAS ___BLANK 1 0"), "model.zmx"));
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_EQ(model.warnings[0].message.rfind("model glass 1.5168/64.17, fitted to the visible, covers 360-830 nm: its index "
                                              "is extrapolated to 1550 nm (n 1.5", 0), 0u)
        << model.warnings[0].message;
}

TEST(ZemaxErrors, AsphereTermOutOfRange) { expectZemaxError(zmxSinglet("  TYPE EVENASPH\n  PARM 9 1"), 14, "PARM 9 is not one"); }
TEST(ZemaxErrors, SurfaceLineBeforeAnySurface) { expectZemaxError(zmxSinglet("  CONI 0", "CURV 0.5"), 2, "CURV before the first SURF"); }

TEST(ZemaxErrors, TooManySurfaces) {
    std::string text = "MODE SEQ\nSURF 0\n  CURV 0\n  DISZ INFINITY\n";
    int lines = 4;
    const auto addLensSurface = [&](int i) {
        text += "SURF " + std::to_string(i) + "\n" + (i == 1 ? "  STOP\n" : "") + "  CURV 0\n  DISZ 1\n  DIAM 5\n";
        lines += i == 1 ? 5 : 4;
    };
    for (int i = 1; i <= kMaxLensSurfaces; ++i) addLensSurface(i);
    EXPECT_EQ(parseZemax(text + "SURF 257\n  CURV 0\n", "max.zmx").rows.size(), std::size_t(kMaxLensSurfaces));
    // SURF 258 is the first that makes 257 lens surfaces (257 being no longer the image).
    addLensSurface(kMaxLensSurfaces + 1);
    expectZemaxError(text + "SURF 258\n", lines + 1, "too many surfaces: a lens may have at most 256 surfaces");
}

TEST(ZemaxErrors, BrokenUtf16) {
    const std::string utf16 = toUtf16(zmxSinglet(), true);
    expectZemaxError(utf16 + "x", 21, "odd number of bytes");  // the file's 20 lines end with a newline
    // A high surrogate followed by a plain character on line 3.
    std::string broken = utf16;
    const std::size_t unit = 2 + 2 * zmxSinglet().find("UNIT");
    broken[unit] = '\x00';
    broken[unit + 1] = '\xd8';
    expectZemaxError(broken, 3, "a high surrogate without a low one");
    broken[unit + 1] = '\xdc';
    expectZemaxError(broken, 3, "a low surrogate without a high one");
    expectZemaxError(std::string("\xff\xfe\x00\xd8", 4), 1, "a high surrogate without a low one");  // at the very end
}
