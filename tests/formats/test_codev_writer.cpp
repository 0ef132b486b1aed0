// The Code V writer keeps everything a .seq holds as lenslab reads it: a lens written and read back
// by parseCodeV is the table as its .seq states it (asCodeVStatesIt), every field exactly equal
// (formats/LensTableDifference.h), and the same lens, surface for surface, ray for ray and by first
// order (1e-12). Every bundled lens; one prescription per group of features, with the Code V
// commands they must appear as; what a .seq cannot hold refused naming its line; the design
// commands' -o out.seq.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>

#include "CodeVWriter.h"
#include "BundledTables.h"
#include "LensTableDifference.h"
#include "PrescriptionJson.h"
#include "TempDir.h"
#include "TextContains.h"
#include "firstorder/FirstOrder.h"
#include "prescription/CodeVFile.h"
#include "prescription/LensSystem.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;
using test::contains;

using test::bundled;
using test::expectLines;

// A lens with model glasses (nd:Vd), air rows of N 1 and a stop row: the features' base.
LensTable modelGlassGauss() { return bundled("dgauss-glass.dat"); }

// Written, read back as a Code V file by its content, compared field by field with the table as the
// .seq states it; the built lenses and their first order before and after; written again, the same
// text.
LensTable expectCodeVRoundTrip(const LensTable& original, const std::string& what = "") {
    const std::string written = writeCodeVText(original);
    const LensTable again = parseLensTable(written, "written.seq");
    EXPECT_EQ(again.format, "seq") << what;
    EXPECT_TRUE(again.warnings.empty()) << what << ": " << again.warnings.front().message;
    const auto difference = lensTableDifference(asCodeVStatesIt(original), again);
    EXPECT_FALSE(difference) << what << ": " << *difference << "\n" << written;
    const auto lens = builtLensDifference(original, again, 1e-12);
    EXPECT_FALSE(lens) << what << ": " << *lens;
    const FirstOrder a = computeFirstOrder(buildLensSystem(original)), b = computeFirstOrder(buildLensSystem(again));
    for (const auto& [x, y] : {std::pair{a.efl, b.efl}, std::pair{a.backFocalDistance, b.backFocalDistance},
                               std::pair{a.zF, b.zF}, std::pair{a.zPPrime, b.zPPrime}})
        EXPECT_NEAR(y, x, 1e-12 * std::max(1.0, std::fabs(x))) << what;
    EXPECT_EQ(writeCodeVText(again), written) << what;
    return again;
}

// The refusal's line and problem, or "written".
std::string refusal(const LensTable& t) {
    try {
        writeCodeVText(t);
    } catch (const LensTableError& e) {
        return std::to_string(e.line()) + ": " + e.problem();
    }
    return "written";
}

// Every bundled lens with dispersive media (catalog and model glasses) comes back; the course's
// tables of plain indices are refused naming their first glass row (lenslab reads a .seq's glass as
// a catalog name or nd:Vd, with dispersion).
TEST(CodeVWriter, EveryBundledLensRoundTripsOrIsRefusedNamingItsPlainIndex) {
    int written = 0, refused = 0;
    for (const fs::path& folder : {fs::path(LENSLAB_SOURCE_DIR) / "lenses", fs::path(LENSLAB_SOURCE_DIR) / "lenses/design"})
        for (const auto& entry : fs::directory_iterator(folder)) {
            const std::string path = entry.path().string();
            if (!isLensFileName(path)) continue;
            const LensTable original = withGapAfterRows(readLensTable(path));
            const auto plain = std::find_if(original.rows.begin(), original.rows.end(), [](const LensTableRow& r) {
                return r.glass.empty() && r.abbe == 0 && r.index > 1 && !r.mirror;
            });
            if (plain != original.rows.end()) {
                EXPECT_TRUE(contains(refusal(original), std::to_string(plain->line) + ": a medium of plain index")) << path << ": " << refusal(original);
                ++refused;
                continue;
            }
            expectCodeVRoundTrip(original, path);
            ++written;
        }
    EXPECT_EQ(written, 6);  // ac254-100-a.dat, dgauss-glass.dat, the three patents' .zmx, the Cooke triplet
    EXPECT_EQ(refused, 8);
}

// The wavelengths and their weights, every kind of field with weights, the object's distance and NA,
// the aperture, the title and notes, surface names, as Code V writes them.
TEST(CodeVWriter, TheDesignsOwnDataComeBack) {
    LensTable t = modelGlassGauss();
    t.comments = {"Double Gauss, F/2", "Tronnier's \"Ultron\""};
    t.wavelengths = {kWavelengthF, kWavelengthD, kWavelengthC};
    t.wavelengthWeights = {1, 2, 0.5};
    t.primaryWavelength = kWavelengthC;
    t.objectDistance = 1234.5;
    t.objectNumericalAperture = 0.01;
    t.entrancePupilDiameter = 20;
    t.designFNumber = 2.5;
    t.rows[0].name = "front's crown";
    t.rows[5].name = "stop";
    ASSERT_EQ(refusal(t), "0: comment 2 'Tronnier's \"Ultron\"' with both kinds of quote in it: a .seq, as lenslab reads it, cannot hold it");
    t.comments[1] = "Tronnier's Ultron";
    expectLines(writeCodeVText(t), {"RDM\nLEN\nTIT 'Double Gauss, F/2'\nTIT \"Tronnier's Ultron\"\nDIM M\n", "WL 486.1327 587.5618 656.2725\nREF 3\nWTW 1 2 0.5\n",
                                    "EPD 20\nFNO 2.5\nNAO 0.01\nSO 0 1234.5\nS 58.95 7.52 1.67:47.1\n  SLB \"front's crown\"\n  CIR 25.2\n",
                                    "S 0 9\n  STO\n  SLB 'stop'\n", "SI 0 0\nGO\n"});
    expectCodeVRoundTrip(t);

    static const char* const kCommands[] = {"AN", "OB", "IM", "RI"};
    for (const FieldType type : {FieldType::ObjectAngle, FieldType::ObjectHeight, FieldType::ParaxialImageHeight, FieldType::RealImageHeight}) {
        t.fields.type = type;
        t.fields.points = {{0, 0, 1}, {0, 10.5, 0.5}, {3.25, -14, 2}};
        const std::string letters = kCommands[int(type)];
        expectLines(writeCodeVText(t), {("X" + letters + " 0 0 3.25\nY" + letters + " 0 10.5 -14\nWTF 1 0.5 2\n").c_str()});
        expectCodeVRoundTrip(t, fieldTypeName(type));
    }
    // At infinity, weights of 0, a primary the list lacks (added to it, as the .zmx writer does).
    t.objectDistance = INFINITY;
    t.objectNumericalAperture.reset();
    t.wavelengthWeights = {0, 1, 3};
    t.primaryWavelength = 550;
    expectLines(writeCodeVText(t), {"WL 486.1327 587.5618 656.2725 550\nREF 4\nWTW 0 1 3 1\n", "SO 0 1e10\n"});
    LensTable withPrimary = t;
    withPrimary.wavelengths.push_back(550);
    withPrimary.wavelengthWeights.push_back(1);
    const LensTable again = parseCodeV(writeCodeVText(t), "written.seq");
    const auto difference = lensTableDifference(asCodeVStatesIt(withPrimary), again);
    EXPECT_FALSE(difference) << *difference;
}

// Catalog glasses by name, with their own catalog (NAME_CATALOG) or the file's catalog list (GCAT),
// which a .seq states on each row; model glasses as nd:Vd; a glass's index beside its name is not
// stated (the catalog decides).
TEST(CodeVWriter, CatalogAndModelGlassesComeBack) {
    LensTable t = bundled("ac254-100-a.dat");
    expectLines(writeCodeVText(t), {"S 62.75 4 N-BK7\n", "S -45.71 2.5 SF5\n"});
    const LensTable again = expectCodeVRoundTrip(t);
    EXPECT_EQ(again.rows[1].index, 0);
    t.rows[1].glassCatalog = "SCHOTT";
    t.catalogs = {"OHARA", "SCHOTT"};
    t.rows[2].glass = "S-TIM2";
    t.rows[2].index = 1.62004;
    expectLines(writeCodeVText(t), {"S 62.75 4 N-BK7_SCHOTT\n", "S -45.71 2.5 S-TIM2_OHARA\n"});
    expectCodeVRoundTrip(t);
    const LensTable cooke = bundled("design/cooke-triplet-50mm.zmx");  // GCAT SCHOTT; SK16, F2
    ASSERT_EQ(cooke.catalogs, std::vector<std::string>{"SCHOTT"});
    expectLines(writeCodeVText(cooke), {" SK16_SCHOTT\n", " F2_SCHOTT\n"});
}

// Conics (CON, K) and even aspheres (ASP, K, A .. G: the r^4 .. r^16 terms).
TEST(CodeVWriter, ConicsAndEvenAspheresComeBack) {
    LensTable t = modelGlassGauss();
    t.rows[0].conic = -0.75;
    t.rows[2].conic = 0.5;
    t.rows[2].aspheric = {0, 1e-6, -2.5e-9, 3e-12, 0, 1.25e-17, -7e-21, 4e-24};
    t.rows[9].aspheric[1] = -3.1e-7;
    expectLines(writeCodeVText(t), {"S 58.95 7.52 1.67:47.1\n  CON\n  K -0.75\n  CIR 25.2\n",
                                    "  ASP\n  K 0.5\n  A 1e-06\n  B -2.5e-09\n  C 3e-12\n  E 1.25e-17\n  F -7e-21\n  G 4e-24\n",
                                    "  ASP\n  A -3.1e-07\n"});
    expectCodeVRoundTrip(t);
}

// Mirrors (REFL), the medium they reflect back into, a central obscuration (CIR OBS): the reflex
// lens's two Mangin mirrors, and a first surface that is a mirror.
TEST(CodeVWriter, MirrorsAndObscurationsComeBack) {
    const LensTable reflex = bundled("us4666259-ex1-reflex-500mm.zmx");
    const std::string written = writeCodeVText(reflex);
    expectLines(written, {"  CIR 38\n  CIR OBS 19\n", " REFL\n"});
    const LensTable again = expectCodeVRoundTrip(reflex);
    EXPECT_EQ(std::count_if(again.rows.begin(), again.rows.end(), [](const LensTableRow& r) { return r.mirror; }), 2);
    // A mirror row stating another medium than the one the light arrives in: the same lens.
    LensTable stated = reflex;
    for (LensTableRow& row : stated.rows)
        if (row.mirror) row.index = 1.5, row.abbe = 40;
    expectCodeVRoundTrip(stated);
}

// Rectangles and ellipses, clear and obscuring, each with its decentre (ADX/ADY); a decentred
// circle; a clear aperture left to the program (no CIR).
TEST(CodeVWriter, ShapedDecentredAndAutomaticAperturesComeBack) {
    LensTable t = modelGlassGauss();
    t.entrancePupilDiameter = 40;
    t.rows[0].clearShape = SurfaceAperture{ApertureKind::Rectangular, 20, 16, 0.5, -0.25};
    t.rows[0].obscurationShape = SurfaceAperture{ApertureKind::Elliptical, 4, 2, -1, 0};
    t.rows[0].diameter = 2 * t.rows[0].clearShape->reach();
    t.rows[1].clearShape = SurfaceAperture{ApertureKind::Elliptical, 24, 18, 0, 0};
    t.rows[1].diameter = 2 * t.rows[1].clearShape->reach();
    t.rows[2].clearShape = SurfaceAperture{ApertureKind::Circular, 20, 20, 0, 1.5};
    t.rows[2].diameter = 2 * t.rows[2].clearShape->reach();
    t.rows[3].obscurationShape = SurfaceAperture{ApertureKind::Rectangular, 3, 1, 0, 0};
    t.rows[4].obscurationShape = SurfaceAperture{ApertureKind::Circular, 2, 2, 0.5, 0};
    t.rows[8].automaticDiameter = true;
    t.rows[8].diameter = 0;
    t.rows[9].obscurationDiameter = 4;
    const std::string written = writeCodeVText(t);
    expectLines(written, {"  REX 20\n  REY 16\n  ADX 0.5\n  ADY -0.25\n  ELX OBS 4\n  ELY OBS 2\n  ADX -1\n",
                          "  ELX 24\n  ELY 18\n", "  CIR 20\n  ADY 1.5\n", "  CIR 23\n  REX OBS 3\n  REY OBS 1\n",
                          "  CIR 18\n  CIR OBS 2\n  ADX 0.5\n", "  CIR 20\n  CIR OBS 2\n"});
    EXPECT_TRUE(contains(written, "S -40.77 0.38\nS 874.13 6.44 1.717:48\n")) << written;  // row 9: no CIR
    expectCodeVRoundTrip(t);
}

// Decentres along x, y and z and tilts about all three axes in each of Code V's modes (basic, DAR,
// BEN, REV), a bend of no tilt, a basic frame of zeros, the image surface's own.
TEST(CodeVWriter, DecentresAndTiltsComeBackInEveryMode) {
    for (const FrameMode mode : {FrameMode::Basic, FrameMode::DecentreAndReturn, FrameMode::Bend, FrameMode::Reverse}) {
        LensTable t = modelGlassGauss();
        t.rows[6].frame = FrameChange{{0.25, -0.5, 0.125}, {1, -0.5, 2}, mode, TiltOrder::DecentreThenTilt};
        t.imageFrame = FrameChange{{0, 0.5, 0}, {0.25, 0, 0}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
        static const char* const kModes[] = {"", "  DAR\n", "  BEN\n", "  REV\n"};
        const std::string lines = "  XDE 0.25\n  YDE -0.5\n  ZDE 0.125\n  ADE 1\n  BDE -0.5\n  CDE 2\n" + std::string(kModes[int(mode)]) + "S ";
        expectLines(writeCodeVText(t), {lines.c_str(), "SI 0 0\n  YDE 0.5\n  ADE 0.25\nGO\n"});
        expectCodeVRoundTrip(t, kModes[int(mode)]);
    }
    LensTable zeros = modelGlassGauss();
    zeros.rows[3].frame = FrameChange{};
    zeros.rows[4].frame = FrameChange{{}, {}, FrameMode::Bend, TiltOrder::DecentreThenTilt};
    expectLines(writeCodeVText(zeros), {"  CIR 23\n  XDE 0\nS", "  CIR 18\n  BEN\nS"});
    expectCodeVRoundTrip(zeros);
}

// A coordinate break of no thickness before a surface (a Zemax file's decentre) is that surface's
// basic decentre, one that moves nothing is nothing: a row fewer each, the same lens.
TEST(CodeVWriter, ACoordinateBreakOfNoThicknessIsTheNextSurfacesDecentre) {
    LensTable t = modelGlassGauss();
    LensTableRow turn;
    turn.coordinateBreak = true;
    turn.index = t.rows[5].index;
    turn.frame = FrameChange{{0.125, -0.25, 0}, {0.5, -0.75, 3}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    t.rows.insert(t.rows.begin() + 6, turn);
    const LensTable again = expectCodeVRoundTrip(t);
    ASSERT_EQ(again.rows.size(), t.rows.size() - 1);
    ASSERT_TRUE(again.rows[6].frame);
    EXPECT_EQ(again.rows[6].frame->tiltDegrees, turn.frame->tiltDegrees);
    EXPECT_EQ(again.rows[6].radius, t.rows[7].radius);
    // One that moves nothing is nothing, before a decentred surface too and as the last row.
    LensTableRow still = turn;
    still.frame = FrameChange{};
    t.rows.insert(t.rows.begin() + 6, still);
    t.rows.push_back(still);
    EXPECT_EQ(expectCodeVRoundTrip(t).rows.size(), t.rows.size() - 3);
}

// A Code V lens read, written and read again is the same table, every field: title, wavelengths and
// weights, fields, aperture, object distance, names, catalog glasses, model glasses by glass code,
// a conic, a decentred rectangle, a returning decentre and tilt, automatic apertures, the image's.
TEST(CodeVWriter, ACodeVLensComesBackAsTheSameTable) {
    const LensTable seq = parseCodeV("RDM\nTITLE 'f/4 achromat'\nEPD 25\nWL 656.2725 587.5618 486.1327\nREF 2\n"
                                     "WTW 1 2 1\nXAN 0 0 1; YAN 0 2.5 5\nWTF 1 2 1\nSO 0 2500\n"
                                     "S 61.47 6.0 NBK7_SCHOTT\nSTO\nSLB 'front'\nCIR 12.5\n"
                                     "S -44.64 2.5 589613\nDAR\nYDE 0.25; ADE 0.5\nCON; K -0.25\n"
                                     "S -129.94 95.95\nREX 10; REY 12; ADY 1\nSI 0 0.05\nYDE 0.1; ADE 0.2\nGO\n",
                                     "achromat.seq");
    const LensTable again = parseCodeV(writeCodeVText(seq), "again.seq");
    const auto difference = lensTableDifference(seq, again);
    EXPECT_FALSE(difference) << *difference;
    expectCodeVRoundTrip(seq);
}

// What a .seq (as lenslab reads it) cannot state is refused naming the row's line and the feature.
TEST(CodeVWriter, WhatASeqCannotStateIsRefusedNamingTheLine) {
    const LensTable lens = modelGlassGauss();
    const int line = lens.rows[2].line;
    const auto expectRefused = [&](const LensTable& t, int at, const std::string& problem) {
        const std::string said = refusal(t);
        EXPECT_TRUE(contains(said, std::to_string(at) + ": " + problem)) << said;
        EXPECT_TRUE(contains(said, ": a .seq, as lenslab reads it, cannot hold it")) << said;
    };
    const auto withRow = [&](const std::function<void(LensTableRow&)>& change) {
        LensTable t = lens;
        change(t.rows[2]);
        return t;
    };
    expectRefused(withRow([](LensTableRow& r) { r.abbe = 0; }), line, "a medium of plain index 1.67 with no Abbe number");
    expectRefused(withRow([](LensTableRow& r) { r.form.kind = SurfaceKind::OddAsphere, r.form.termCount = 1, r.form.terms[0] = 1e-4; }), line,
                  "a surface of the kind odd asphere");
    expectRefused(withRow([](LensTableRow& r) { r.form.kind = SurfaceKind::Qbfs, r.form.normalisationRadius = 10; }), line,
                  "a surface of the kind Qbfs");
    expectRefused(withRow([](LensTableRow& r) { r.form.kind = SurfaceKind::Toroidal, r.form.termCount = 1; }), line,
                  "a surface of the kind toroidal");
    expectRefused(withRow([](LensTableRow& r) { r.aspheric[0] = 1e-4; }), line, "an r^2 aspheric term");
    expectRefused(withRow([](LensTableRow& r) { r.coating = "MgF2"; }), line, "the coating 'MgF2'");
    expectRefused(withRow([](LensTableRow& r) { r.frame = FrameChange{{0, 1, 0}, {2, 0, 0}, FrameMode::Basic, TiltOrder::TiltThenDecentre}; }),
                  line, "a tilt before the decentre");
    expectRefused(withRow([](LensTableRow& r) { r.glass = "REFL", r.abbe = 0; }), line, "a glass name 'REFL'");
    expectRefused(withRow([](LensTableRow& r) { r.glass = "1.5:40", r.abbe = 0; }), line, "a glass name '1.5:40'");
    expectRefused(withRow([](LensTableRow& r) { r.glass = "N-BK7;SI", r.abbe = 0; }), line, "a glass name 'N-BK7;SI'");
    expectRefused(withRow([](LensTableRow& r) { r.glass = "L-TIM28_MOLD", r.abbe = 0; }), line, "glass 'L-TIM28_MOLD' with no catalog");
    expectRefused(withRow([](LensTableRow& r) { r.glass = "N-BK7", r.glassCatalog = "MY_SCHOTT", r.abbe = 0; }), line,
                  "catalog 'MY_SCHOTT' with an underscore");
    expectRefused(withRow([](LensTableRow& r) { r.name = "a 'b' \"c\""; }), line, "a surface name 'a 'b' \"c\"' with both kinds of quote");
    expectRefused(withRow([](LensTableRow& r) { r.name = "a\nGO"; }), line, "a surface name with a control character");
    expectRefused(withRow([](LensTableRow& r) { r.stop = true; }), lens.rows[5].line, "a second stop");
    expectRefused(withRow([](LensTableRow& r) { r.diameter = 0; }), line, "a clear aperture of diameter 0");
    expectRefused(withRow([](LensTableRow& r) { r.clearShape = SurfaceAperture{ApertureKind::Circular, 20, 20, 0, 0}; }), line,
                  "a circular clear aperture about the vertex given as a shape");
    expectRefused(withRow([](LensTableRow& r) { r.obscurationDiameter = 2, r.obscurationShape = SurfaceAperture{ApertureKind::Rectangular, 1, 1, 0, 0}; }),
                  line, "a central obscuration and a shaped one");
    LensTable apart = lens;  // a coordinate break with a thickness of its own
    LensTableRow turn;
    turn.coordinateBreak = true;
    turn.gap = 0.5;
    turn.line = 99;
    turn.frame = FrameChange{{0, 0.5, 0}, {}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    apart.rows.insert(apart.rows.begin() + 6, turn);
    expectRefused(apart, 99, "a coordinate break other than the decentre of the surface after it");

    LensTable t = lens;
    t.rows[5].stop = false;
    expectRefused(t, 0, "a lens without a stop");
    t = lens;
    t.imageFrame = FrameChange{{0, 1, 0}, {}, FrameMode::DecentreAndReturn, TiltOrder::DecentreThenTilt};
    expectRefused(t, 0, "an image surface decentre that returns");
    t = lens;
    t.objectDistance = 2e10;
    expectRefused(t, 0, "an object distance of 1e10 mm or more");
    t = lens;
    t.wavelengths.assign(25, 550);
    t.primaryWavelength = 550;
    expectRefused(t, 0, "25 wavelengths");
    t = lens;
    t.wavelengths = {100};
    expectRefused(t, 0, "the wavelength 100 nm lies outside");
    t = lens;
    t.fields.type = FieldType::ObjectHeight;
    expectRefused(t, 0, "a field type (object height) without fields");
    t = lens;
    t.comments = {"one", ""};
    expectRefused(t, 0, "comment 2, an empty line");
    t = lens;
    t.substitutes.push_back({"D-ZK3M", "N-BK7", "SCHOTT", std::nullopt, "lens.smx:2"});
    EXPECT_EQ(refusal(t), "0: glasses substituted by lens.smx:2: lenslab does not write them into a .seq (the .smx beside it holds them)");
    EXPECT_TRUE(contains(refusal(readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.dat")), "0: a .seq needs gap-after rows"));
}

// `lenslab optimise -o out.seq` and `lenslab tolerance --format seq` write Code V files, each read
// back by the command to the same merit before it is kept.
TEST(CodeVWriter, TheDesignCommandsWriteSeqFiles) {
    const test::TempDir dir;
    const std::string triplet = LENSLAB_SOURCE_DIR "/lenses/design/cooke-triplet-50mm.zmx";
    const std::string merit = LENSLAB_SOURCE_DIR "/bench/design/cooke-merit.json";
    const auto run = [&](const std::string& args) {
        return std::system((std::string(LENSLAB_BINARY) + " " + args + " > " + dir.path() + "/log 2>&1").c_str());
    };
    ASSERT_EQ(run("optimise " + triplet + " --merit " + merit + " --variables curvature:1-6 --max-iterations 3 -o " + dir.path() + "/out.seq"), 0);
    const LensTable optimised = readLensTable(dir.path() + "/out.seq");
    EXPECT_EQ(optimised.format, "seq");
    EXPECT_EQ(optimised.rows.size(), 6u);
    ASSERT_EQ(run("tolerance " + triplet + " --merit " + merit + " --trials 5 --format seq -o " + dir.path() + "/tolerance"), 0);
    const LensTable p90 = readLensTable(dir.path() + "/tolerance/p90.seq");
    EXPECT_EQ(p90.format, "seq");
    EXPECT_EQ(p90.substitutes.size(), 3u);  // the as-built melts, from p90.smx beside it
    EXPECT_TRUE(buildLensSystem(p90).decentred);
    EXPECT_NE(run("tolerance " + triplet + " --trials 0 --format dat -o " + dir.path()), 0);
}

}  // namespace
}  // namespace lenslab
