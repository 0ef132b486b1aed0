// Round trips through the writers: every bundled lens written as .zmx (and as .dat where a table
// can hold it) and parsed again gives the same rows, and the same lens (EFL); the editor's JSON
// rows read back to the same table; what a .dat cannot hold is refused naming the row.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "settings/LensAnalysis.h"
#include "prescription/LensSystem.h"
#include "LensTableWriter.h"
#include "PrescriptionJson.h"
#include "ZemaxWriter.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> bundledLenses() {
    std::vector<std::string> paths;
    for (const auto& entry : fs::directory_iterator(fs::path(LENSLAB_SOURCE_DIR) / "lenses"))
        if (isLensFileName(entry.path().string())) paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

// 1 / (1 / r) may differ from r in the last bit (a .zmx stores curvature); everything else is exact.
void expectSameRows(const LensTable& a, const LensTable& b, const std::string& what) {
    ASSERT_EQ(a.rows.size(), b.rows.size()) << what;
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        const LensTableRow &x = a.rows[i], &y = b.rows[i];
        const std::string row = what + " row " + std::to_string(i + 1);
        EXPECT_NEAR(x.radius, y.radius, 1e-12 * std::fabs(x.radius)) << row;
        EXPECT_EQ(x.gap, y.gap) << row;
        // Air is N 0 or 1 in a table; a stop is N 0.
        const auto medium = [](const LensTableRow& r) { return r.glass.empty() && r.index == 1 ? 0.0 : r.index; };
        EXPECT_EQ(medium(x), medium(y)) << row;
        EXPECT_EQ(x.diameter, y.diameter) << row;
        EXPECT_EQ(x.stop, y.stop) << row;
        EXPECT_EQ(x.glass, y.glass) << row;
        EXPECT_EQ(x.abbe, y.abbe) << row;
        EXPECT_EQ(x.conic, y.conic) << row;
        EXPECT_EQ(x.aspheric, y.aspheric) << row;
        EXPECT_EQ(x.mirror, y.mirror) << row;
        EXPECT_EQ(x.obscurationDiameter, y.obscurationDiameter) << row;
        EXPECT_EQ(x.coating, y.coating) << row;
    }
}

double efl(const LensTable& table) {
    return analyzeLens(buildLensSystem(table), std::nullopt, INFINITY).firstOrder.efl;
}

bool tableCanHold(const LensTable& t) {
    for (const LensTableRow& r : t.rows)
        if (r.conic != 0 || r.mirror || r.obscurationDiameter > 0 || r.aspheric != AsphericCoefficients{}) return false;
    return true;
}

TEST(PrescriptionWriters, EveryBundledLensRoundTripsThroughZemax) {
    for (const std::string& path : bundledLenses()) {
        const LensTable original = withGapAfterRows(readLensTable(path));
        const LensTable again = parseLensTable(writeZemaxText(original), "written.zmx");
        expectSameRows(original, again, path + " via .zmx");
        EXPECT_EQ(again.comments, original.comments) << path;
        EXPECT_EQ(again.catalogs, original.catalogs) << path;
        EXPECT_NEAR(again.primaryWavelength, original.primaryWavelength, 1e-9) << path;
        EXPECT_NEAR(efl(again), efl(original), 1e-9 * std::fabs(efl(original))) << path;
    }
}

TEST(PrescriptionWriters, EveryLensATableCanHoldRoundTripsThroughDat) {
    int written = 0;
    for (const std::string& path : bundledLenses()) {
        const LensTable original = readLensTable(path);
        if (!tableCanHold(original)) {
            EXPECT_THROW(writeLensTableText(original), LensTableError) << path;
            continue;
        }
        const LensTable again = parseLensTable(writeLensTableText(original), "written.dat", original.layout);
        expectSameRows(original, again, path + " via .dat");
        EXPECT_EQ(again.comments.size(), original.comments.size() + 1) << path << ": the column header is a comment";
        EXPECT_NEAR(efl(again), efl(original), 1e-12 * std::fabs(efl(original))) << path;
        ++written;
    }
    EXPECT_GE(written, 10);
}

TEST(PrescriptionWriters, AZemaxCatalogGlassGetsItsCatalogIndexInADat) {
    LensTable t = parseLensTable("VERS 1\nMODE SEQ\nSURF 0\n CURV 0\n DISZ INFINITY\nSURF 1\n CURV 0.02\n DISZ 5\n"
                                 " GLAS N-BK7 0 0 0 0\n DIAM 10\n STOP\nSURF 2\n CURV -0.02\n DISZ 40\n DIAM 10\n"
                                 "SURF 3\n CURV 0\n DISZ 0\n", "singlet.zmx");
    t.rows[0].stop = false;  // a .dat stop is a flat air row: add one in front
    LensTableRow stop;
    stop.stop = true;
    stop.diameter = 8;
    stop.gap = 1;
    t.rows.insert(t.rows.begin(), stop);
    const std::string text = writeLensTableText(t);
    EXPECT_NE(text.find(" 1.5168"), std::string::npos) << text;
    EXPECT_NEAR(efl(parseLensTable(text, "singlet.dat", TableLayout::GapAfter)), efl(t), 1e-9);
}

TEST(PrescriptionWriters, ADatRefusesAConicNamingItsRow) {
    LensTable t = readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    t.rows[2].conic = -1;
    try {
        writeLensTableText(t);
        FAIL() << "a conic was written into a .dat";
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), t.rows[2].line);
        EXPECT_NE(e.problem().find(".zmx"), std::string::npos) << e.problem();
    }
}

// A prescription's coatings (bare, a stack, a layer in nm) come back from every writer, and rows
// without one keep the default.
TEST(PrescriptionWriters, CoatingsRoundTripThroughZmxDatAndJson) {
    LensTable t = readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    t.rows[0].coating = "none";
    t.rows[1].coating = "MgF2+ZrO2:2q+Al2O3@510";
    t.rows[9].coating = "1.38:99.6nm";
    const LensTable viaZmx = parseLensTable(writeZemaxText(t), "written.zmx");
    const LensTable viaDat = parseLensTable(writeLensTableText(t), "written.dat", t.layout);
    const LensTable viaJson = prescriptionFromJson(prescriptionJson(t), "edited");
    for (const LensTable* again : {&viaZmx, &viaDat, &viaJson}) {
        expectSameRows(t, *again, "coated dgauss.50mm");
        const LensSystem lens = buildLensSystem(*again);
        EXPECT_TRUE(lens.surfaces[0].coating.bare());
        EXPECT_EQ(lens.surfaces[1].coating.layers.size(), 3u);
        EXPECT_DOUBLE_EQ(lens.surfaces[9].coating.layers.at(0).thicknessNm, 99.6);
        EXPECT_TRUE(lens.surfaces[2].coating.isDefault);
    }
    EXPECT_NE(writeZemaxText(t).find("  COAT MgF2+ZrO2:2q+Al2O3@510\n"), std::string::npos);
    EXPECT_NE(writeLensTableText(t).find(" coat=none\n"), std::string::npos);
}

TEST(PrescriptionJson, RowsReadBackToTheSameTable) {
    for (const std::string& path : bundledLenses()) {
        const LensTable original = withGapAfterRows(readLensTable(path));
        const LensTable again = prescriptionFromJson(prescriptionJson(original), "edited");
        expectSameRows(original, again, path + " via JSON");
        EXPECT_NEAR(efl(again), efl(original), 1e-12 * std::fabs(efl(original))) << path;
    }
}

TEST(PrescriptionJson, AGapBeforeTableMovesItsGapsUpOneRow) {
    const LensTable before = readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.dat");
    ASSERT_EQ(before.layout, TableLayout::GapBefore);
    const LensTable after = withGapAfterRows(before);
    EXPECT_EQ(after.rows[0].gap, before.rows[1].gap);
    EXPECT_EQ(after.rows.back().gap, 0);
    EXPECT_NEAR(efl(after), efl(before), 1e-12 * std::fabs(efl(before)));
}

TEST(PrescriptionJson, ABadFieldNamesItsRow) {
    nlohmann::json body = prescriptionJson(readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"));
    body["rows"][3]["diameter"] = -2;
    try {
        prescriptionFromJson(body, "edited");
        FAIL() << "a negative diameter was accepted";
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 4);
        EXPECT_NE(e.problem().find("diameter"), std::string::npos);
    }
    body["rows"][3]["diameter"] = "wide";
    EXPECT_THROW(prescriptionFromJson(body, "edited"), LensTableError);
}

}  // namespace
}  // namespace lenslab
