// The live editor's JSON keeps everything the writers write: a lens sent to the page
// (prescriptionJson, as text), read back from it (prescriptionFromJson) and written as .zmx is the
// stored lens's own download, and reads back as the same table, every field exactly equal
// (formats/LensTableDifference.h). For every bundled lens, and for prescriptions written here in the
// style of the public ones: a plate tilted by coordinate breaks with a field list and FNUM, a Q-type
// asphere with a rectangular aperture, a Code V lens with returning tilts, automatic apertures, row
// catalogs, an image decentre and ENPD. An edited radius changes the radius and nothing else.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <tuple>

#include "TextContains.h"
#include "LensTableDifference.h"
#include "PrescriptionJson.h"
#include "ZemaxWriter.h"
#include "prescription/LensSystem.h"
#include "prescription/ZemaxFile.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

// The page's round trip: the JSON as the service sends it (text), and back as the page posts it.
LensTable throughTheEditor(const LensTable& stored, const std::function<void(nlohmann::json&)>& edit = {}) {
    nlohmann::json sent = nlohmann::json::parse(prescriptionJson(stored).dump());
    if (edit) edit(sent);
    return prescriptionFromJson(nlohmann::json::parse(sent.dump()), "edited lens");
}

// The edited lens is the stored one, field for field; its .zmx is the stored lens's download, and
// reads back as the stored table (its rows' Code V catalogs as the file's GCAT).
void expectKeptThroughTheEditor(const LensTable& source, const std::string& what) {
    const LensTable stored = withGapAfterRows(source);
    const LensTable edited = throughTheEditor(stored);
    const auto kept = lensTableDifference(stored, edited);
    EXPECT_FALSE(kept) << what << " through the JSON: " << *kept;
    const std::string written = writeZemaxText(edited);
    EXPECT_EQ(written, writeZemaxText(stored)) << what << ": the edited lens's .zmx is not the stored lens's";
    const auto again = lensTableDifference(withRowCatalogsInTheFile(stored), parseZemax(written, "written.zmx"));
    EXPECT_FALSE(again) << what << " read back: " << *again << "\n" << written;
}

using test::contains;

TEST(EditorJson, EveryBundledLensIsKeptThroughTheEditor) {
    int lenses = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(LENSLAB_SOURCE_DIR) / "lenses"))
        if (isLensFileName(entry.path().string())) {
            expectKeptThroughTheEditor(readLensTable(entry.path().string()), entry.path().filename().string());
            ++lenses;
        }
    EXPECT_EQ(lenses, 13);
}

// A BK7 plate tilted 10 degrees about x between coordinate breaks (the second turning back), before
// a singlet; five fields of real image height with weights, FNUM, three weighted wavelengths with C
// the primary, an object at 2 m, surface names.
const char* const kTiltedPlateZmx = R"(VERS 190513 0 0
MODE SEQ
NAME tilted plate and singlet
NOTE 0 written for lenslab's tests
UNIT MM X W X CM MR CPMM
FNUM 4.5 0
GCAT SCHOTT
FTYP 3 0 5 3 0 0 0
XFLN 0 0 0 1.5 0 0 0 0 0 0 0 0
YFLN 0 2 4.25 3 -6 0 0 0 0 0 0 0
FWGN 1 0.5 2 1 0.25 1 1 1 1 1 1 1
WAVM 1 0.4861327 1
WAVM 2 0.5875618 2
WAVM 3 0.6562725 0.5
PWAV 3
SURF 0
  TYPE STANDARD
  CURV 0
  DISZ 2000
SURF 1
  COMM tilt in
  TYPE COORDBRK
  CURV 0
  DISZ 0
  PARM 1 0
  PARM 2 0.25
  PARM 3 10
  PARM 4 0
  PARM 5 0
  PARM 6 0
SURF 2
  COMM plate front
  TYPE STANDARD
  CURV 0
  DISZ 4
  GLAS N-BK7 0 0 1.5168 64.17
  DIAM 8
SURF 3
  TYPE STANDARD
  CURV 0
  DISZ 0
  DIAM 8
SURF 4
  COMM tilt back
  TYPE COORDBRK
  CURV 0
  DISZ 5
  PARM 1 0
  PARM 2 -0.25
  PARM 3 -10
  PARM 4 0
  PARM 5 0
  PARM 6 1
SURF 5
  TYPE STANDARD
  CURV 0.02
  DISZ 5
  GLAS N-BK7 0 0 1.5168 64.17
  DIAM 10
  STOP
SURF 6
  TYPE STANDARD
  CURV -0.02
  DISZ 45
  DIAM 10
SURF 7
  TYPE STANDARD
  CURV 0
  DISZ 0
)";

// A Qbfs asphere (three terms, normalisation radius 9.5) behind a rectangular aperture with an
// elliptical obscuration decentred with it, an odd asphere, a toroid, ENPD.
const char* const kQTypeZmx = R"(VERS 190513 0 0
MODE SEQ
NAME Q-type and shapes
UNIT MM X W X CM MR CPMM
ENPD 12
SURF 0
  TYPE STANDARD
  CURV 0
  DISZ INFINITY
SURF 1
  TYPE QTYPE
  XDAT 1 1
  XDAT 2 3
  XDAT 3 9.5
  XDAT 4 0.001
  XDAT 5 -0.0002
  XDAT 6 5e-05
  CURV 0.025
  DISZ 6
  GLAS N-BK7 0 0 0 0
  DIAM 10
  SQAP 7 5 0
  ELOB 1.5 1 0
  OBDC 0.5 -0.25
  STOP
SURF 2
  TYPE ODDASPH
  PARM 1 0
  PARM 2 1e-05
  PARM 3 3e-07
  CURV -0.01
  DISZ 3
  DIAM 10
SURF 3
  TYPE TOROIDAL
  PARM 1 60
  PARM 2 1e-06
  CURV 0.01
  DISZ 4
  GLAS ___BLANK 1 0 1.6 40
  DIAM 10
SURF 4
  TYPE STANDARD
  CURV -0.015
  DISZ 60
  DIAM 10
SURF 5
  TYPE STANDARD
  CURV 0
  DISZ 0
)";

// Code V: a plate decentred and tilted about y by returning decentres (DAR), surfaces without CIR
// (automatic apertures), glasses with their catalog (N-SF5_SCHOTT), fields in object angle, EPD, the
// image decentred.
const char* const kTiltedCodeV = R"(RDM
TITLE 'returning tilts'
EPD 8
WL 486.1327 587.5618 656.2725
REF 2
WTW 1 2 1
XAN 0 0 1; YAN 0 3 5
WTF 1 1 0.5
SO 0 1e10
S 0 3 N-SF5_SCHOTT
  DAR
  XDE 0.5; BDE -7
S 0 6
  DAR
  XDE 0.5; BDE -7
S 60 4.5 N-BK7_SCHOTT
STO
S -40 52
SI 0 0
  YDE 0.1
GO
)";

TEST(EditorJson, PrescriptionsInThePublicFilesStyleAreKeptThroughTheEditor) {
    const LensTable plate = parseLensTable(kTiltedPlateZmx, "tilted-plate.zmx");
    ASSERT_TRUE(plate.rows[0].coordinateBreak && plate.rows[0].frame);
    ASSERT_EQ(plate.fields.points.size(), 5u);
    ASSERT_TRUE(plate.designFNumber);
    expectKeptThroughTheEditor(plate, "tilted-plate.zmx");

    const LensTable q = parseLensTable(kQTypeZmx, "q-type.zmx");
    ASSERT_EQ(q.rows[0].form.kind, SurfaceKind::Qbfs);
    ASSERT_TRUE(q.rows[0].clearShape && q.rows[0].clearShape->kind == ApertureKind::Rectangular);
    ASSERT_EQ(q.rows[2].form.kind, SurfaceKind::Toroidal);
    expectKeptThroughTheEditor(q, "q-type.zmx");

    const LensTable seq = parseLensTable(kTiltedCodeV, "tilted.seq");
    ASSERT_TRUE(seq.rows[0].frame && seq.rows[0].frame->mode == FrameMode::DecentreAndReturn);
    ASSERT_TRUE(seq.rows[0].automaticDiameter);
    ASSERT_EQ(seq.rows[0].glassCatalog, "SCHOTT");
    ASSERT_TRUE(seq.imageFrame);
    expectKeptThroughTheEditor(seq, "tilted.seq");
}

// What the page does: one radius changed in the rows it was sent. The tilt, the fields, FNUM, the
// wavelengths, names and the object distance stay; the first (and only) difference is that radius.
TEST(EditorJson, AnEditedRadiusChangesThatRadiusAndNothingElse) {
    const LensTable plate = parseLensTable(kTiltedPlateZmx, "tilted-plate.zmx");
    const LensTable edited = throughTheEditor(plate, [](nlohmann::json& lens) { lens["rows"][4]["radius"] = 48; });
    EXPECT_EQ(lensTableDifference(plate, edited), "row 5 radius: 50 / 48");
    LensTable expected = plate;
    expected.rows[4].radius = 48;
    EXPECT_FALSE(lensTableDifference(expected, edited));
    const std::string zmx = writeZemaxText(edited);
    for (const char* line : {"  TYPE COORDBRK\n  CURV 0\n  DISZ 0\n  PARM 1 0\n  PARM 2 0.25\n  PARM 3 10\n",
                             "  PARM 3 -10\n  PARM 4 0\n  PARM 5 0\n  PARM 6 1\n", "\nFTYP 3 0 5 3 0 0 0\n",
                             "\nYFLN 0 2 4.25 3 -6 0 0 0 0 0 0 0\n", "\nFNUM 4.5 0\n", "\nPWAV 3\n", "  COMM plate front\n",
                             "  DISZ 2000\n", "  CURV 0.020833333333333333\n"})
        EXPECT_TRUE(contains(zmx, line)) << line << " in\n" << zmx;
}

// A body of rows alone (as the editor sent before it kept the rest) reads as before: no fields,
// aperture or tilts, the object at infinity.
TEST(EditorJson, RowsAloneTakeTheTablesDefaults) {
    nlohmann::json body = prescriptionJson(parseLensTable(kTiltedPlateZmx, "tilted-plate.zmx"));
    nlohmann::json rows = body["rows"];
    for (nlohmann::json& row : rows)
        for (const char* kept : {"frame", "coordinate_break", "kind", "form_terms", "normalisation_radius", "clear_aperture",
                                 "obscuration", "automatic_diameter", "name", "glass_catalog"})
            row.erase(kept);
    rows.erase(rows.begin() + 3);  // the returning break: a row with no surface once its frame is gone
    rows.erase(rows.begin());
    const LensTable t = prescriptionFromJson({{"rows", rows}}, "edited lens");
    EXPECT_TRUE(t.fields.points.empty());
    EXPECT_FALSE(t.designFNumber || t.entrancePupilDiameter || t.objectNumericalAperture || t.imageFrame);
    EXPECT_EQ(t.objectDistance, INFINITY);
    EXPECT_EQ(t.primaryWavelength, kWavelengthD);
    for (const LensTableRow& r : t.rows) EXPECT_FALSE(r.frame || r.coordinateBreak || r.clearShape || !r.form.isEvenAsphere());
}

// What the editor's JSON cannot mean is refused naming the row and the field.
TEST(EditorJson, AKeptFieldThatCannotBeIsRefusedNamingItsRow) {
    const nlohmann::json good = prescriptionJson(parseLensTable(kTiltedPlateZmx, "tilted-plate.zmx"));
    const nlohmann::json q = prescriptionJson(parseLensTable(kQTypeZmx, "q-type.zmx"));
    const auto refusal = [](nlohmann::json body, const std::function<void(nlohmann::json&)>& change) -> std::string {
        change(body);
        try {
            prescriptionFromJson(body, "edited lens");
        } catch (const LensTableError& e) {
            return std::to_string(e.line()) + ": " + e.problem();
        }
        return "accepted";
    };
    const std::vector<std::tuple<nlohmann::json, std::function<void(nlohmann::json&)>, std::string>> cases = {
        {good, [](auto& b) { b["rows"][0]["frame"]["mode"] = "sideways"; },
         "1: frame.mode must be one of \"basic\", \"decentre and return\", \"bend\", \"reverse\""},
        {good, [](auto& b) { b["rows"][0]["frame"]["tilt_degrees"] = {10, 0}; }, "1: frame.tilt_degrees must be a list of 3"},
        {good, [](auto& b) { b["rows"][0]["frame"] = nullptr; }, "1: a coordinate break needs its frame"},
        {good, [](auto& b) { b["rows"][0]["diameter"] = 8; }, "1: a coordinate break has no surface: its diameter must be 0"},
        {good, [](auto& b) { b["rows"][1]["diameter"] = 0; }, "2: diameter must be positive"},
        {good, [](auto& b) { b["fields"]["type"] = "image angle"; }, "0: fields.type must be one of \"object angle\""},
        {good, [](auto& b) { b["fields"]["points"][2]["weight"] = -1; }, "0: fields.points 3.weight must not be negative"},
        {good, [](auto& b) { b["f_number"] = 0; }, "0: f_number must be positive"},
        {good, [](auto& b) { b["object_distance"] = "far"; }, "0: object_distance must be a number"},
        {good, [](auto& b) { b["wavelength_weights"] = {1, 1, 1, 1}; }, "0: more wavelength_weights than wavelengths_nm"},
        {good, [](auto& b) { b["image_frame"] = {{"decentre", {0, 1, 0}}}; }, "0: image_frame.tilt_degrees must be a list of 3"},
        {q, [](auto& b) { b["rows"][0]["kind"] = "Qfoo"; }, "1: kind must be one of \"even asphere\""},
        {q, [](auto& b) { b["rows"][1]["form_terms"] = std::vector<double>(17, 0.0); }, "2: form_terms must be a list of at most 16"},
        {q, [](auto& b) { b["rows"][0]["clear_aperture"]["shape"] = "hexagonal"; }, "1: clear_aperture.shape must be one of"},
        {q, [](auto& b) { b["rows"][0]["clear_aperture"]["half_width_y"] = -5; }, "1: clear_aperture.half_width_x and half_width_y must be positive"},
        {q, [](auto& b) { b["rows"][0]["diameter"] = 20; }, "1: diameter must be " + nlohmann::json(2 * std::hypot(7.5, 5.25)).dump() +
                                                                " mm, what the clear aperture's shape reaches"},
        {q, [](auto& b) { b["rows"][0]["obscuration"] = "round"; }, "1: obscuration must be an object"},
    };
    for (const auto& [body, change, expected] : cases) {
        const std::string got = refusal(body, change);
        EXPECT_EQ(got.substr(0, expected.size()), expected) << got;
    }
}

}  // namespace
}  // namespace lenslab
