// The Code V .seq reader: every command in its place and unit, radius and curvature modes,
// continuations and comments, encodings, the file's own fields and wavelengths, private glasses,
// decentres and apertures, and every refusal with its file:line and command. The files here are
// the tests' own, written from the numbers they check.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ParaxialYNu.h"
#include "Utf16.h"
#include "firstorder/FirstOrder.h"
#include "prescription/CodeVFile.h"
#include "prescription/GlassCatalog.h"
#include "prescription/LensSystem.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

// An f/4 achromat in the form Code V writes: radii (RDM), metres as millimetres, F d C.
std::string achromat(const std::string& extraSurfaceLine = "", const std::string& header = "RDM;LEN \"test\"") {
    return header + "\n"                                   // 1
           "TITLE 'f/4 achromat'\n"                         // 2
           "EPD 25.0\n"                                     // 3
           "DIM M\n"                                        // 4
           "WL 656.2725 587.5618 486.1327\n"                // 5
           "REF 2\n"                                        // 6
           "WTW 1 2 1\n"                                    // 7
           "XAN 0 0 0; YAN 0 2.5 5\n"                       // 8
           "WTF 1 2 1\n"                                    // 9
           "SO 0 1e11\n"                                    // 10
           "S 61.47 6.0 NBK7_SCHOTT\n"                      // 11
           "  STO\n"                                        // 12
           "  SLB \"front\"\n"                              // 13
           "  CIR 12.5\n"                                   // 14
           "S -44.64 2.5 NSF5_SCHOTT\n" +                   // 15
           extraSurfaceLine + "\n"                          // 16
           "S -129.94 95.95\n"                              // 17
           "  CIR 12.5\n"                                   // 18
           "SI 0 0.05\n"                                    // 19
           "GO\n";                                          // 20
}

void expectCodeVError(const std::string& text, int line, const std::string& part) {
    expectReadError([&] { parseCodeV(text, "bad.seq"); }, text, "bad.seq", line, part);
}

double catalogIndex(const std::string& glass, double nm) { return refractiveIndex(*findGlass(glass).glass, nm); }

}  // namespace

TEST(CodeV, AchromatRowsHeaderAndFields) {
    const LensTable t = parseCodeV(achromat(), "achromat.seq");
    EXPECT_EQ(t.format, "seq");
    EXPECT_EQ(t.layout, TableLayout::GapAfter);
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_DOUBLE_EQ(t.rows[0].radius, 61.47);
    EXPECT_DOUBLE_EQ(t.rows[1].radius, -44.64);
    EXPECT_DOUBLE_EQ(t.rows[0].gap, 6.0);
    EXPECT_DOUBLE_EQ(t.rows[2].gap, 95.95 + 0.05);  // SI's thickness defocuses the image
    EXPECT_EQ(t.rows[0].glass, "NBK7");
    EXPECT_EQ(t.rows[0].glassCatalog, "SCHOTT");
    EXPECT_EQ(t.rows[2].glass, "");
    EXPECT_TRUE(t.rows[0].stop);
    EXPECT_FALSE(t.rows[1].stop);
    EXPECT_EQ(t.rows[0].name, "front");
    EXPECT_DOUBLE_EQ(t.rows[0].diameter, 25);
    EXPECT_FALSE(t.rows[0].automaticDiameter);
    EXPECT_TRUE(t.rows[1].automaticDiameter);  // no CIR
    EXPECT_EQ(t.rows[0].line, 11);
    EXPECT_EQ(t.rows[2].line, 17);
    ASSERT_EQ(t.comments.size(), 1u);
    EXPECT_EQ(t.comments[0], "f/4 achromat");
    EXPECT_EQ(t.wavelengths, (std::vector<double>{656.2725, 587.5618, 486.1327}));
    EXPECT_EQ(t.wavelengthWeights, (std::vector<double>{1, 2, 1}));
    EXPECT_DOUBLE_EQ(t.primaryWavelength, 587.5618);
    ASSERT_TRUE(t.entrancePupilDiameter);
    EXPECT_DOUBLE_EQ(*t.entrancePupilDiameter, 25);
    EXPECT_FALSE(std::isfinite(t.objectDistance));  // SO 1e11: at infinity
    EXPECT_EQ(t.fields.type, FieldType::ObjectAngle);
    ASSERT_EQ(t.fields.points.size(), 3u);
    EXPECT_DOUBLE_EQ(t.fields.points[2].y, 5);
    EXPECT_DOUBLE_EQ(t.fields.points[1].weight, 2);
}

// The built lens's focal length against an independent y-nu trace of the file's own numbers with
// the catalog's indices: the reader put every radius, gap and glass where the optics reads it.
TEST(CodeV, AchromatFocalLengthAgainstParaxialTrace) {
    const LensSystem lens = buildLensSystem(parseCodeV(achromat(), "achromat.seq"));
    const double n1 = catalogIndex("N-BK7", kWavelengthD), n2 = catalogIndex("N-SF5", kWavelengthD);
    std::vector<test::YNuSurface> sys = {{0, 1 / 61.47, 1, n1}, {6, -1 / 44.64, n1, n2}, {8.5, -1 / 129.94, n2, 1}};
    const test::YNu out = test::traceYNu(sys, 0, 1, 0);
    const double efl = -1 / out.u;
    EXPECT_NEAR(computeFirstOrder(lens).efl, efl, 1e-7 * efl);
    EXPECT_NEAR(efl, 100, 2);  // an f/4 100 mm achromat, as designed
    // The surface without CIR is sized by the file's aperture (EPD 25) and field (5 deg); the stop is the EPD's.
    EXPECT_NEAR(lens.surfaces[0].apertureRadius, 12.5, 1e-12);
    EXPECT_TRUE(lens.surfaces[1].automaticAperture);
    // Surface 2's: 1.1 times the marginal ray's height plus the 5 degree chief ray's (through the
    // stop's centre on surface 1), both paraxial, 6 mm behind surface 1 in the lens's own glass.
    const std::vector<test::YNuSurface> front = {{0, 1 / 61.47, 1, lens.surfaces[0].indexAfter}};
    const test::YNu marginal = test::traceYNu(front, 0, 12.5, 0), chief = test::traceYNu(front, 0, 0, std::tan(5 * M_PI / 180));
    const double expected = 1.1 * (std::fabs(marginal.y + 6 * marginal.u) + std::fabs(chief.y + 6 * chief.u));
    EXPECT_NEAR(lens.surfaces[1].apertureRadius, expected, 1e-9);
}

TEST(CodeV, CurvatureModeAndUnitsAndContinuations) {
    // RDM N: curvatures; DIM I: inches; '&' continues a line, '!' starts a comment, ';' separates.
    const std::string text =
        "rdm n ! curvatures follow\n"
        "dim i\n"
        "so 0 1e10\n"
        "s 0.05 &\n"
        " 0.2 n-bk7_schott ; sto\n"
        "s -.025 2 ! an aspheric back\n"
        "asp; k -0.5; a 1e-4; b -2e-6\n"
        "epd 1; wl 550\n";
    const LensTable t = parseCodeV(text, "inches.seq");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_NEAR(t.rows[0].radius, 25.4 / 0.05, 1e-9);
    EXPECT_NEAR(t.rows[0].gap, 0.2 * 25.4, 1e-12);
    EXPECT_NEAR(t.rows[1].radius, -25.4 / 0.025, 1e-9);
    EXPECT_TRUE(t.rows[0].stop);
    EXPECT_EQ(t.rows[0].glass, "n-bk7");
    EXPECT_DOUBLE_EQ(t.rows[1].conic, -0.5);
    // A is the r^4 term (lens unit^-3), B the r^6 term: in mm they shrink by 25.4^3 and 25.4^5.
    EXPECT_NEAR(t.rows[1].aspheric[1], 1e-4 / std::pow(25.4, 3), 1e-20);
    EXPECT_NEAR(t.rows[1].aspheric[2], -2e-6 / std::pow(25.4, 5), 1e-24);
    EXPECT_EQ(t.rows[1].aspheric[0], 0);
    EXPECT_NEAR(*t.entrancePupilDiameter, 25.4, 1e-12);
    EXPECT_EQ(t.rows[1].line, 6);
}

// Commands spelled out past their three letters are the three-letter command (Code V reads
// TITLE, STOP, CIRCLE so): the field and aperture letters come from that name, not the spelling.
TEST(CodeV, SpelledOutCommandsAreTheirThreeLetterCommand) {
    const std::string text = "title 'long names'\nso 0 1e10\ns 40 5 1.6,40\nstop\ncircle 6\ns -60 30\n"
                             "yangle 0 7\nepd 10; wl 550\n";
    const LensTable t = parseCodeV(text, "long.seq");
    EXPECT_TRUE(t.rows[0].stop);
    EXPECT_FALSE(t.rows[0].clearShape);  // a circle about the vertex is the diameter
    EXPECT_FALSE(t.rows[0].automaticDiameter);
    EXPECT_DOUBLE_EQ(t.rows[0].diameter, 12);
    EXPECT_EQ(t.fields.type, FieldType::ObjectAngle);
    ASSERT_EQ(t.fields.points.size(), 2u);
    EXPECT_DOUBLE_EQ(t.fields.points[1].y, 7);
}

TEST(CodeV, RadiusAndCurvatureModesAgree) {
    const LensTable radii = parseCodeV(achromat(), "a.seq");
    std::string curvatures = achromat("", "RDM N;LEN");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"S 61.47 6.0", "S 0.016268098259 6.0"},
                                   {"S -44.64 2.5", "S -0.022401433692 2.5"},
                                   {"S -129.94 95.95", "S -0.007695859628 95.95"}})
        curvatures.replace(curvatures.find(from), from.size(), to);
    const LensTable c = parseCodeV(curvatures, "c.seq");
    for (std::size_t i = 0; i < radii.rows.size(); ++i) EXPECT_NEAR(c.rows[i].radius, radii.rows[i].radius, 1e-6);
}

TEST(CodeV, Utf16ReadsAsUtf8AndDispatchesByContent) {
    const LensTable utf8 = parseCodeV(achromat(), "a.seq");
    for (const bool littleEndian : {true, false}) {
        const std::string bytes = test::toUtf16(achromat(), littleEndian);
        const LensTable t = parseLensTable(bytes, "a.txt");  // the name says nothing: the content does
        EXPECT_EQ(t.format, "seq");
        ASSERT_EQ(t.rows.size(), utf8.rows.size());
        for (std::size_t i = 0; i < t.rows.size(); ++i) EXPECT_EQ(t.rows[i].radius, utf8.rows[i].radius);
        EXPECT_EQ(t.rows[2].line, 17);
    }
    EXPECT_TRUE(looksLikeCodeV("! a comment\nRDM;LEN\n"));
    EXPECT_TRUE(looksLikeCodeV("tit 'x'\n"));
    EXPECT_FALSE(looksLikeCodeV("50 0 1.5 20\n"));
    EXPECT_FALSE(looksLikeCodeV("VERS 140124\n"));
    EXPECT_FALSE(looksLikeCodeV(""));
}

TEST(CodeV, FictitiousGlasses) {
    const std::string text = "so 0 1e10\ns 0.01 2 1.6,40\nsto\ns 0 1 589613\ns -0.01 1 517000.520000\ns 0 1 569.631\n"
                             "s 0 1 AIR\nepd 2\n";
    const LensTable t = parseCodeV(text, "f.seq");
    EXPECT_DOUBLE_EQ(t.rows[0].index, 1.6);
    EXPECT_DOUBLE_EQ(t.rows[0].abbe, 40);
    EXPECT_DOUBLE_EQ(t.rows[1].index, 1.589);
    EXPECT_DOUBLE_EQ(t.rows[1].abbe, 61.3);
    EXPECT_NEAR(t.rows[2].index, 1.517, 1e-12);
    EXPECT_NEAR(t.rows[2].abbe, 52, 1e-9);
    EXPECT_NEAR(t.rows[3].index, 1.569, 1e-12);
    EXPECT_NEAR(t.rows[3].abbe, 63.1, 1e-9);
    EXPECT_EQ(t.rows[4].index, 0);
    EXPECT_EQ(t.rows[4].glass, "");
    // Six characters strtod reads as a number but no glass code: a catalog's name, looked up later.
    for (const std::string glass : {"0x1p-3", "1e+100", "inf000"}) {
        const LensTable named = parseCodeV("so 0 1e10\ns 50 5 " + glass + "\nsto\ns -50 45\nsi 0 0\n", "g.seq");
        EXPECT_EQ(named.rows[0].index, 0) << glass;
        EXPECT_NE(named.rows[0].glass, "") << glass;
    }
    // A model glass holds its figures: n_d and (n_d - 1) / (n_F - n_C).
    const LensSystem lens = buildLensSystem(t);
    const Medium& g = lens.surfaces[1].mediumAfter;
    EXPECT_NEAR(refractiveIndex(g, kWavelengthD), 1.589, 1e-12);
    EXPECT_NEAR(abbeNumber(g), 61.3, 1e-9);
}

TEST(CodeV, PrivateCatalogGlasses) {
    const std::string text =
        "PRV\n"
        "PWL 700 600 500 400\n"
        "'G1' 1.510 1.515 1.522 1.534\n"
        "'L1' LAU 2.3639 0.0 0.025493 -0.00058 -3.5e-6 4.45e-8\n"
        "END\n"
        "so 0 1e10\ns 0.02 3 'G1'\nsto\ns 0 2 'L1'\ns 0 10\nepd 5; wl 600 550\n";
    const LensSystem lens = buildLensSystem(parseCodeV(text, "p.seq"));
    // The table holds at its wavelengths; between them a smooth curve.
    const Medium& g = lens.surfaces[0].mediumAfter;
    EXPECT_EQ(g.formula, DispersionFormula::Tabulated);
    EXPECT_NEAR(refractiveIndex(g, 600), 1.515, 1e-12);
    EXPECT_NEAR(refractiveIndex(g, 400), 1.534, 1e-12);
    const double mid = refractiveIndex(g, 550);
    EXPECT_GT(mid, 1.515);
    EXPECT_LT(mid, 1.522);
    EXPECT_NEAR(refractiveIndex(g, 300), 1.534, 1e-12);  // held beyond the table
    // Laurent: n^2 = A0 + A1 L^2 + A2 L^-2 + A3 L^-4 + A4 L^-6 + A5 L^-8, L in micrometres.
    const double l = 0.55, n2 = 2.3639 + 0.025493 / (l * l) - 0.00058 / std::pow(l, 4) - 3.5e-6 / std::pow(l, 6) +
                                4.45e-8 / std::pow(l, 8);
    EXPECT_NEAR(refractiveIndex(lens.surfaces[1].mediumAfter, 550), std::sqrt(n2), 1e-12);
    EXPECT_DOUBLE_EQ(lens.primaryWavelength, 600);  // REF defaults to the first wavelength
}

// A mirror sends the ray back through the medium it came from: its row holds that medium (as a
// .zmx's does), so the two readers' tables of one Mangin mirror agree.
TEST(CodeV, AMirrorRowHoldsTheMediumItReflectsIn) {
    const LensTable t = parseCodeV("so 0 1e10\ns 100 5 NBK7_SCHOTT\nsto\ncir 10\ns -200 -5 refl\ncir 10\n"
                                   "s 100 -50\ncir 10\nepd 10; wl 587.5618\n", "mangin.seq");
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_TRUE(t.rows[1].mirror);
    EXPECT_EQ(t.rows[1].glass, "NBK7");
    EXPECT_EQ(t.rows[1].glassCatalog, "SCHOTT");
    EXPECT_EQ(t.rows[2].glass, "");
}

TEST(CodeV, DecentresTiltsAndApertures) {
    const std::string text =
        "so 0 1e10\n"
        "s 0 10\nsto\n"                            // 2-3
        "s -200 -50 refl\ncon; k -1\n"             // 4-5
        "dar\nyde 2.5; ade 3; xde -1\n"            // 6-7
        "rex 10; rey 12; ady 4\n"                  // 8
        "cir obs l'A' 2; cir edg 30\n"             // 9
        "s 0 20 refl\nade 45; ben\n"               // 10-11
        "s 0 5\nrev; bde -2; zde 0.5\n"            // 12-13
        "elx 3; ely 4\n"                           // 14
        "si 0 0\nyde 1; ade 0.5\n"                 // 15-16
        "epd 20; wl 550; yan 0 0.1\n";
    const LensTable t = parseCodeV(text, "d.seq");
    ASSERT_EQ(t.rows.size(), 4u);
    const LensTableRow& m = t.rows[1];
    EXPECT_TRUE(m.mirror);
    EXPECT_DOUBLE_EQ(m.conic, -1);
    ASSERT_TRUE(m.frame);
    EXPECT_EQ(m.frame->mode, FrameMode::DecentreAndReturn);
    EXPECT_EQ(m.frame->decentre, (std::array<double, 3>{-1, 2.5, 0}));
    EXPECT_EQ(m.frame->tiltDegrees, (std::array<double, 3>{3, 0, 0}));
    ASSERT_TRUE(m.clearShape);
    EXPECT_EQ(m.clearShape->kind, ApertureKind::Rectangular);
    EXPECT_DOUBLE_EQ(m.clearShape->halfWidthX, 10);
    EXPECT_DOUBLE_EQ(m.clearShape->halfWidthY, 12);
    EXPECT_DOUBLE_EQ(m.clearShape->centreY, 4);
    EXPECT_DOUBLE_EQ(m.obscurationDiameter, 4);  // CIR OBS with a label; CIR EDG is not a clear aperture
    EXPECT_DOUBLE_EQ(m.diameter, 2 * std::sqrt(10.0 * 10 + 16 * 16));  // the circle holding the rectangle's far corner
    EXPECT_EQ(t.rows[2].frame->mode, FrameMode::Bend);
    EXPECT_EQ(t.rows[3].frame->mode, FrameMode::Reverse);
    EXPECT_EQ(t.rows[3].frame->decentre, (std::array<double, 3>{0, 0, 0.5}));
    EXPECT_EQ(t.rows[3].frame->tiltDegrees, (std::array<double, 3>{0, -2, 0}));
    EXPECT_EQ(t.rows[3].clearShape->kind, ApertureKind::Elliptical);
    ASSERT_TRUE(t.imageFrame);
    EXPECT_EQ(t.imageFrame->decentre, (std::array<double, 3>{0, 1, 0}));
    EXPECT_EQ(t.imageFrame->tiltDegrees, (std::array<double, 3>{0.5, 0, 0}));
}

TEST(CodeV, StopDefaultsToTheFirstSurface) {
    const LensTable t = parseCodeV("rdm y\nso 0 1e10\ns -200 -100 refl\nsi 0 0\nfno 8; wl 550\n", "p.seq");
    ASSERT_EQ(t.rows.size(), 1u);
    EXPECT_TRUE(t.rows[0].stop);
    ASSERT_TRUE(t.designFNumber);
    EXPECT_DOUBLE_EQ(*t.designFNumber, 8);
}

TEST(CodeV, AFileCutShortIsReadWithAWarningNamingItsLastLine) {
    // The achromat cut after its second surface (line 15): its rear surface, SI and GO lost. It
    // still reads as a lens, of two surfaces, so the reader says where the file stopped.
    const std::string whole = achromat();
    std::size_t cut = 0;
    for (int line = 0; line < 15; ++line) cut = whole.find('\n', cut) + 1;
    const LensTable t = parseCodeV(whole.substr(0, cut), "cut.seq");
    EXPECT_EQ(t.rows.size(), 2u);
    ASSERT_EQ(t.warnings.size(), 1u);
    EXPECT_EQ(t.warnings[0].line, 15);
    EXPECT_EQ(t.warnings[0].message, "cut.seq ends at line 15 with neither an image surface (SI) nor GO: the file may be cut short; "
                                     "read as the 2 surfaces it gives");
    // The whole file, and one that ends at its image surface without GO, are read without one.
    EXPECT_TRUE(parseCodeV(whole, "whole.seq").warnings.empty());
    EXPECT_TRUE(parseCodeV(whole.substr(0, whole.rfind("GO")), "no-go.seq").warnings.empty());
}

TEST(CodeVErrors, EveryRefusalNamesTheLineAndCommand) {
    expectCodeVError(achromat("  FOO 1"), 16, "command FOO is not read");
    expectCodeVError(achromat("  DIF DOE"), 16, "DIF");
    expectCodeVError(achromat("  ASP; H 1e-9"), 15, "aspheric term H");
    expectCodeVError(achromat("  STO"), 15, "a second stop");
    expectCodeVError("so 0 1e10\nsto 50 5 n-bk7_schott\ns -50 45\nsi 0 0\n", 2, "STO takes no values");
    expectCodeVError(achromat("  ARO 10"), 16, "rotated apertures");
    expectCodeVError(achromat("  CIR -1"), 16, "positive semi-aperture");
    expectCodeVError(achromat("  K"), 16, "K needs at least 1 value");
    expectCodeVError(achromat("  K 1e999"), 16, "not a finite number");
    expectCodeVError(achromat("  S 1"), 16, "S needs a radius");
    expectCodeVError(achromat("REF 4"), 16, "REF 4 names no WL wavelength");
    expectCodeVError("so 0 1e10\ns 50 5 58961!\nsto\ns -50 45\nsi 0 0\n", 2, "glass code 58961 is not nd and Vd");
    expectCodeVError("so 0 1e10\ns 50 5 " + std::string(1000, '9') + "\nsto\ns -50 45\nsi 0 0\n", 2, "glass code");
    expectCodeVError(achromat("REF 1e11"), 16, "REF names a wavelength by its number (1..24), found 1e11");
    expectCodeVError(achromat("WL 587.56 3390"), 16, "WL: wavelength 3390 nm lies outside 180-2500 nm");
    expectCodeVError(achromat("", "DIM Q"), 1, "DIM Q is not one of");
    expectCodeVError(achromat("", "STO"), 1, "STO before the first surface");
    expectCodeVError("so 0 1\nsi 0 0\n", 2, "no lens surfaces");
    expectCodeVError("so 0 1e10\ns 0 1\nsi 20 0\n", 3, "curved image surface");
    expectCodeVError("so 0 1e10\ns 0 1\n'G' 1.5 1.6\n", 3, "between PRV and END");
    expectCodeVError("PRV\nPWL 500 600\n'G' 1.5\nEND\n", 3, "lists 1 indices for the 2 wavelengths");
    expectCodeVError("title 'x\n", 1, "quoted string is not closed");
    expectCodeVError("", 1, "empty file");
}
