// The .zmx writer keeps everything a .zmx holds: a lens written and read back is the same table,
// every field exactly equal (formats/LensTableDifference.h), and builds the same first order. One
// synthetic prescription per group of features (the design's own data; catalogs; coordinate
// breaks and decentres; surface forms; apertures), and the Zemax lines they must appear as.
#include <gtest/gtest.h>

#include <cmath>

#include "TextContains.h"
#include "BundledTables.h"
#include "LensTableDifference.h"
#include "PrescriptionJson.h"
#include "ZemaxWriter.h"
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "prescription/ZemaxFile.h"

namespace lenslab {
namespace {

using test::bundled;
using test::expectLines;

using test::contains;

// Written, read back, compared field by field; the built lens's first order before and after.
LensTable expectZemaxRoundTrip(const LensTable& original) {
    const std::string written = writeZemaxText(original);
    const LensTable again = parseZemax(written, "written.zmx");
    const auto difference = lensTableDifference(original, again);
    EXPECT_FALSE(difference) << *difference << "\n" << written;
    const FirstOrder a = computeFirstOrder(buildLensSystem(original)), b = computeFirstOrder(buildLensSystem(again));
    for (const auto& [x, y] : {std::pair{a.efl, b.efl}, std::pair{a.backFocalDistance, b.backFocalDistance},
                               std::pair{a.zF, b.zF}, std::pair{a.zPPrime, b.zPPrime}})
        EXPECT_NEAR(y, x, 1e-12 * std::max(1.0, std::fabs(x)));
    return again;
}

// The wavelengths and their weights, the field list, the object's distance and NA, the aperture,
// the title, notes and surface names, as Zemax writes them.
TEST(ZemaxRoundTrip, TheDesignsOwnDataComeBack) {
    LensTable t = bundled("dgauss.50mm.dat");
    t.comments = {"Double Gauss, F/2", "a second note"};
    t.wavelengths = {kWavelengthF, kWavelengthD, kWavelengthC};
    t.wavelengthWeights = {1, 2, 0.5};
    t.primaryWavelength = kWavelengthD;
    t.fields.type = FieldType::ObjectAngle;
    t.fields.points = {{0, 0, 1}, {0, 10.5, 0.5}, {3.25, -14, 2}};
    t.objectDistance = 1234.5;
    t.objectNumericalAperture = 0.01;
    t.entrancePupilDiameter = 20;
    t.designFNumber = 2.5;
    t.rows[0].name = "front crown";
    t.rows[5].name = "stop";
    const std::string written = writeZemaxText(t);
    // Zemax's own lines: three fields and three wavelengths, 12 field slots, micrometres and weights.
    expectLines(written, {"\nFTYP 0 0 3 3 0 0 0\n",
                          "\nXFLN 0 0 3.25 0 0 0 0 0 0 0 0 0\n",
                          "\nYFLN 0 10.5 -14 0 0 0 0 0 0 0 0 0\n",
                          "\nFWGN 1 0.5 2 1 1 1 1 1 1 1 1 1\n",
                          "\nWAVM 2 0.5875618 2\n",
                          "\nOBNA 0.01 0\n",
                          "SURF 0\n  TYPE STANDARD\n  CURV 0\n  DISZ 1234.5\n",
                          "SURF 1\n  COMM front crown\n"});
    expectZemaxRoundTrip(t);

    // Image heights in mm, another primary, weights of 0.
    t.fields.type = FieldType::RealImageHeight;
    t.fields.points = {{0, 0, 1}, {0, 21.6, 0}};
    t.primaryWavelength = kWavelengthC;
    t.wavelengthWeights = {0, 1, 3};
    t.objectDistance = INFINITY;
    t.objectNumericalAperture.reset();
    expectZemaxRoundTrip(t);
}

// A wavelength in nm written in micrometres reads back as the same double, also where the double
// nearest nm / 1000, times 1000, is an ulp off.
TEST(ZemaxRoundTrip, WavelengthsComeBackExactly) {
    LensTable t = bundled("dgauss.50mm.dat");
    int offByAnUlp = 0;
    for (double nm = 400.0; nm < 700; nm += 0.37) {
        offByAnUlp += nm / 1000 * 1000 != nm;
        t.wavelengths = {nm, kWavelengthD};
        t.wavelengthWeights = {1, 1};
        const LensTable again = parseZemax(writeZemaxText(t), "written.zmx");
        ASSERT_EQ(again.wavelengths.size(), 2u);
        EXPECT_EQ(again.wavelengths[0], nm);
    }
    EXPECT_GT(offByAnUlp, 0) << "no wavelength tested where the plain quotient is off";
    // All 24 slots, the last ones what Zemax writes in unused slots: still the table's.
    t.wavelengths.assign(24, 550);
    t.wavelengths[0] = kWavelengthD;
    t.wavelengthWeights.assign(24, 1);
    EXPECT_EQ(parseZemax(writeZemaxText(t), "written.zmx").wavelengths.size(), 24u);
}

// A Code V row's catalog (N-BK7_SCHOTT) becomes the file's GCAT; read back, the same glass.
TEST(ZemaxRoundTrip, ARowsCatalogIsTheFilesCatalog) {
    LensTable t = bundled("dgauss.50mm.dat");
    t.rows[0].glass = "N-BK7";
    t.rows[0].glassCatalog = "SCHOTT";
    t.rows[0].index = 0;
    const std::string written = writeZemaxText(t);
    expectLines(written, {"\nGCAT SCHOTT\n"});
    LensTable expected = t;
    expected.catalogs = {"SCHOTT"};
    expected.rows[0].glassCatalog.clear();
    const auto stated = lensTableDifference(withRowCatalogsInTheFile(t), expected);
    EXPECT_FALSE(stated) << *stated;
    const LensTable again = expectZemaxRoundTrip(expected);
    EXPECT_EQ(computeFirstOrder(buildLensSystem(again)).efl, computeFirstOrder(buildLensSystem(t)).efl);
}

// Coordinate breaks (PARM 1-6 with the order flag), a surface's own decentre and tilt (SCBD 1),
// the image surface's.
TEST(ZemaxRoundTrip, CoordinateBreaksDecentresAndTiltsComeBack) {
    LensTable t = bundled("dgauss.50mm.dat");
    LensTableRow turn;
    turn.coordinateBreak = true;
    turn.gap = 0.0625;
    turn.index = t.rows[1].index, turn.glass = t.rows[1].glass, turn.abbe = t.rows[1].abbe;  // the medium it sits in
    turn.frame = FrameChange{{0.125, -0.25, 0}, {0.5, -0.75, 3}, FrameMode::Basic, TiltOrder::TiltThenDecentre};
    turn.name = "turn";
    LensTableRow back = turn;
    back.gap = 0;
    back.frame = FrameChange{{-0.125, 0.25, 0}, {-0.5, 0.75, -3}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    t.rows[1].gap -= turn.gap;
    t.rows.insert(t.rows.begin() + 2, turn);
    t.rows.insert(t.rows.begin() + 3, back);
    t.rows[6].frame = FrameChange{{0.0625, 0.03125, 0}, {0.25, 0.5, -1}, FrameMode::DecentreAndReturn, TiltOrder::TiltThenDecentre};
    t.imageFrame = FrameChange{{0, 1, 0}, {0.5, 0, 0}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    const std::string written = writeZemaxText(t);
    expectLines(written, {"  TYPE COORDBRK\n  CURV 0\n  DISZ 0.0625\n  PARM 1 0.125\n  PARM 2 -0.25\n  PARM 3 0.5\n"
                          "  PARM 4 -0.75\n  PARM 5 3\n  PARM 6 1\n",
                          "  SCBD 1 1 0 0.0625 0.03125 0.25 0.5 -1\n"});
    expectZemaxRoundTrip(t);
}

// Odd aspheres, toroids, Qbfs and Qcon with their terms.
TEST(ZemaxRoundTrip, SurfaceFormsComeBack) {
    LensTable t = bundled("dgauss.50mm.dat");
    t.rows[0].form.kind = SurfaceKind::OddAsphere;
    t.rows[0].form.terms = {0, 1e-5, 3e-7, -2e-9};
    t.rows[0].form.termCount = 4;
    t.rows[1].form.kind = SurfaceKind::Toroidal;
    t.rows[1].form.terms = {t.rows[1].radius, 1e-6, -1e-9};
    t.rows[1].form.termCount = 3;
    t.rows[2].form.kind = SurfaceKind::Qbfs;
    t.rows[2].form.normalisationRadius = 11.5;
    t.rows[2].form.terms = {1e-3, -2e-4, 5e-5};
    t.rows[2].form.termCount = 3;
    t.rows[8].form.kind = SurfaceKind::Qcon;
    t.rows[8].conic = -0.5;
    t.rows[8].form.normalisationRadius = 10;
    t.rows[8].form.terms = {2e-4, 0, -1e-5};
    t.rows[8].form.termCount = 3;
    const std::string written = writeZemaxText(t);
    expectLines(written, {"  TYPE ODDASPH\n",
                          "  TYPE QTYPE\n  XDAT 1 1\n  XDAT 2 3\n  XDAT 3 11.5\n  XDAT 4 0.001\n",
                          "  TYPE QTYPE\n  XDAT 1 0\n"});
    expectZemaxRoundTrip(t);
}

// Rectangles and ellipses, clear and obscuring, decentred together (OBDC); a decentred circle; a
// clear aperture left to the program (DIAM 0).
TEST(ZemaxRoundTrip, ShapedDecentredAndAutomaticAperturesComeBack) {
    LensTable t = bundled("dgauss.50mm.dat");
    t.entrancePupilDiameter = 20;
    t.rows[0].clearShape = SurfaceAperture{ApertureKind::Rectangular, 10, 8, 0.5, -0.25};
    t.rows[0].obscurationShape = SurfaceAperture{ApertureKind::Elliptical, 2, 1, 0.5, -0.25};
    t.rows[0].diameter = 2 * t.rows[0].clearShape->reach();
    t.rows[1].clearShape = SurfaceAperture{ApertureKind::Elliptical, 12, 9, 0, 0};
    t.rows[1].diameter = 2 * t.rows[1].clearShape->reach();
    t.rows[2].clearShape = SurfaceAperture{ApertureKind::Circular, 10, 10, 0, 0.75};
    t.rows[2].diameter = 2 * t.rows[2].clearShape->reach();
    t.rows[3].obscurationShape = SurfaceAperture{ApertureKind::Rectangular, 1.5, 0.5, 0, 0};
    t.rows[8].automaticDiameter = true;
    t.rows[8].diameter = 0;
    const std::string written = writeZemaxText(t);
    expectLines(written, {"  SQAP 10 8 0\n  ELOB 2 1 0\n  OBDC 0.5 -0.25\n",
                          "  DIAM 10\n  OBDC 0 0.75\n",
                          "  DIAM 0\n"});
    expectZemaxRoundTrip(t);
}

// A Code V decentre whose coordinates do not return (basic, BEN, REV) is Zemax's coordinate breaks
// around the surface: rows of their own when read back, and the same lens, surface for surface and
// ray for ray (to 1e-12), by lenslab's own motions for each mode (prescription/FrameChange.h).
TEST(ZemaxRoundTrip, ADecentreThatDoesNotReturnIsWrittenAsCoordinateBreaks) {
    const LensTable lens = bundled("dgauss.50mm.dat");
    for (const FrameMode mode : {FrameMode::Basic, FrameMode::Bend, FrameMode::Reverse})
        for (const TiltOrder order : {TiltOrder::DecentreThenTilt, TiltOrder::TiltThenDecentre}) {
            LensTable t = lens;
            t.rows[6].frame = FrameChange{{0.25, -0.5, 0}, {1, -0.5, 2}, mode, order};
            const LensTable again = parseZemax(writeZemaxText(t), "written.zmx");
            const std::string what = std::to_string(int(mode)) + "/" + std::to_string(int(order));
            ASSERT_EQ(again.rows.size(), t.rows.size() + (mode == FrameMode::Bend ? 2 : 1)) << what;
            const LensTableRow& lensRow = again.rows[mode == FrameMode::Reverse ? 6 : 7];
            EXPECT_EQ(lensRow.radius, t.rows[6].radius) << what;
            EXPECT_FALSE(lensRow.frame) << what;
            if (mode != FrameMode::Reverse) {
                ASSERT_TRUE(again.rows[6].coordinateBreak) << what;
                EXPECT_EQ(again.rows[6].frame->tiltDegrees, t.rows[6].frame->tiltDegrees) << what;
                EXPECT_EQ(again.rows[6].gap, 0) << what;
            } else {
                const LensTableRow& back = again.rows[7];
                ASSERT_TRUE(back.coordinateBreak) << what;
                EXPECT_EQ(back.frame->decentre, (std::array<double, 3>{-0.25, 0.5, 0})) << what;
                EXPECT_EQ(back.frame->tiltDegrees, (std::array<double, 3>{-1, 0.5, -2})) << what;
                EXPECT_NE(back.frame->order, order) << what;
                EXPECT_EQ(back.gap, t.rows[6].gap) << what;
            }
            const auto difference = builtLensDifference(t, again, 1e-12);
            EXPECT_FALSE(difference) << what << ": " << *difference;
        }
}

// A Code V lens read, written as .zmx and read back is the same table, once its rows' catalogs are
// the file's (GCAT): its title, wavelengths and weights, fields and their weights, aperture, object
// distance, surface names, catalog glasses, a decentred rectangle, a returning decentre and tilt,
// automatic apertures and the image's decentre.
TEST(ZemaxRoundTrip, ACodeVLensComesBackAsTheSameTable) {
    const LensTable seq = parseLensTable("RDM\nTITLE 'f/4 achromat'\nEPD 25\nWL 656.2725 587.5618 486.1327\nREF 2\n"
                                         "WTW 1 2 1\nXAN 0 0 1; YAN 0 2.5 5\nWTF 1 2 1\nSO 0 2500\n"
                                         "S 61.47 6.0 NBK7_SCHOTT\nSTO\nSLB 'front'\nCIR 12.5\n"
                                         "S -44.64 2.5 NSF5_SCHOTT\nDAR\nYDE 0.25; ADE 0.5\n"
                                         "S -129.94 95.95\nREX 10; REY 12; ADY 1\nSI 0 0.05\nYDE 0.1; ADE 0.2\n",
                                         "achromat.seq");
    ASSERT_EQ(seq.format, "seq");
    ASSERT_TRUE(seq.rows[1].automaticDiameter);
    ASSERT_TRUE(seq.imageFrame);
    const LensTable again = parseZemax(writeZemaxText(seq), "achromat.zmx");
    const auto difference = lensTableDifference(withRowCatalogsInTheFile(seq), again);
    EXPECT_FALSE(difference) << *difference;
    EXPECT_EQ(again.catalogs, (std::vector<std::string>{"SCHOTT"}));
    const auto lens = builtLensDifference(seq, again, 1e-12);
    EXPECT_FALSE(lens) << *lens;
}

// What a .zmx (as lenslab reads it) cannot state is refused naming the row and the feature.
TEST(ZemaxRoundTrip, WhatAZmxCannotStateIsRefusedByName) {
    const auto refusal = [](const LensTable& t) -> std::string {
        try {
            writeZemaxText(t);
        } catch (const LensTableError& e) {
            return std::to_string(e.line()) + ": " + e.problem();
        }
        return "written";
    };
    const LensTable lens = bundled("dgauss.50mm.dat");
    LensTable z = lens;
    z.rows[2].frame = FrameChange{{0, 0, 0.5}, {}, FrameMode::DecentreAndReturn, TiltOrder::DecentreThenTilt};
    EXPECT_TRUE(contains(refusal(z), "a decentre along z")) << refusal(z);
    LensTable ring = lens;
    ring.rows[2].obscurationShape = SurfaceAperture{ApertureKind::Circular, 2, 2, 0, 1};
    EXPECT_TRUE(contains(refusal(ring), "a decentred circular obscuration")) << refusal(ring);
    LensTable apart = lens;
    apart.rows[2].clearShape = SurfaceAperture{ApertureKind::Rectangular, 10, 8, 0.5, 0};
    apart.rows[2].obscurationShape = SurfaceAperture{ApertureKind::Rectangular, 1, 1, 0, 0};
    EXPECT_TRUE(contains(refusal(apart), "decentred differently")) << refusal(apart);
    LensTable blank = lens;
    blank.rows[1].index = 0;
    blank.rows[1].abbe = 40;  // would read back as an unreadable ___BLANK line
    EXPECT_TRUE(contains(refusal(blank), "a model glass of nd 0, Vd 40")) << refusal(blank);
    LensTable both = lens;
    both.rows[0].glass = "N-BK7";
    both.rows[0].abbe = 64.17;  // a catalog glass's GLAS line has no Vd of its own
    EXPECT_TRUE(contains(refusal(both), "with an Abbe number besides")) << refusal(both);
    LensTable substituted = lens;
    substituted.substitutes.push_back({"D-ZK3M", "N-BK7", "SCHOTT", std::nullopt, "lens.smx:2"});
    EXPECT_TRUE(contains(refusal(substituted), "0: glasses substituted by lens.smx:2")) << refusal(substituted);
}

}  // namespace
}  // namespace lenslab
