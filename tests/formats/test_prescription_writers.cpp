// Round trips through the writers: every bundled lens written as .zmx (and as .dat where a table
// can hold it) and parsed again gives the same rows, and the same lens (EFL); the editor's JSON
// rows read back to the same table; what a .dat cannot hold is refused naming the row.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <tuple>
#include <filesystem>

#include "firstorder/FirstOrder.h"
#include "settings/LensAnalysis.h"
#include "prescription/GlassCatalog.h"
#include "prescription/LensSystem.h"
#include "LensTableDifference.h"
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

// Every number exact, the radius too (a .zmx stores its curvature).
void expectSameRows(const LensTable& a, const LensTable& b, const std::string& what) {
    ASSERT_EQ(a.rows.size(), b.rows.size()) << what;
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        const LensTableRow &x = a.rows[i], &y = b.rows[i];
        const std::string row = what + " row " + std::to_string(i + 1);
        EXPECT_EQ(x.radius, y.radius) << row;
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

// A glass its name finds differently with the file's catalog order than without it.
bool catalogOrderMatters(const LensTable& t, const LensTableRow& r) {
    if (r.glass.empty() || t.catalogs.empty()) return false;
    const GlassLookup with = findGlass(r.glass, t.catalogs), without = findGlass(r.glass);
    return with.glass && without.glass && (with.glass->name != without.glass->name || with.glass->catalog != without.glass->catalog);
}

bool tableCanHold(const LensTable& t) {
    if (t.primaryWavelength != kWavelengthD) return false;
    for (const LensTableRow& r : t.rows)
        if (r.conic != 0 || r.mirror || r.obscurationDiameter > 0 || r.aspheric != AsphericCoefficients{} ||
            catalogOrderMatters(t, r))
            return false;
    return true;
}

TEST(PrescriptionWriters, EveryBundledLensRoundTripsThroughZemax) {
    for (const std::string& path : bundledLenses()) {
        const LensTable original = withGapAfterRows(readLensTable(path));
        const LensTable again = parseLensTable(writeZemaxText(original), "written.zmx");
        expectSameRows(original, again, path + " via .zmx");
        const auto difference = lensTableDifference(original, again);
        EXPECT_FALSE(difference) << path << ": " << *difference;
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

// What a Code V or Zemax file brings and a .dat does not hold (a decentre, an aperture left to
// the program) is refused naming its row: never written as a different lens. A .zmx holds both.
TEST(PrescriptionWriters, FeaturesTheWritersDoNotHoldAreRefusedNamingTheRow) {
    const std::string tilted = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ncir 10\ns -60 10\ncir 10\ns 0 20\ncir 10\n"
                               "yde 0.5; ade 3; dar\nepd 10; wl 587.5618\n";
    const std::string automatic = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ncir 10\ns -60 10\nepd 10; wl 587.5618\n";
    for (const auto& [text, line, feature] : {std::make_tuple(tilted, 8, "a decentre or tilt"),
                                              std::make_tuple(automatic, 6, "a clear aperture the file leaves to the program")}) {
        const LensTable t = parseLensTable(text, "in.seq");
        try {
            writeLensTableText(t);
            FAIL() << feature << " was written";
        } catch (const LensTableError& e) {
            EXPECT_EQ(e.line(), line) << e.what();
            EXPECT_NE(e.problem().find(feature), std::string::npos) << e.what();
        }
        const LensTable again = parseLensTable(writeZemaxText(t), "in.zmx");
        EXPECT_EQ(again.rows[1].frame.has_value(), t.rows[1].frame.has_value()) << feature;
        EXPECT_EQ(again.rows[1].automaticDiameter, t.rows[1].automaticDiameter) << feature;
    }
    // Without them the same lens is written and reads back with its first order.
    const LensTable plain = parseLensTable(
        "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ncir 10\ns -60 10\ncir 10\nepd 10; wl 587.5618\n", "plain.seq");
    const double efl = computeFirstOrder(buildLensSystem(plain)).efl;
    EXPECT_NEAR(computeFirstOrder(buildLensSystem(parseLensTable(writeZemaxText(plain), "plain.zmx"))).efl, efl, 1e-9 * efl);
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

// ---- what the writers cannot hold (issue 32) ----------------------------------------------------

LensTable dgauss() { return withGapAfterRows(readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat")); }

using Writer = std::string (*)(const LensTable&);

// The writer refuses the table (LensTableError), or writes text that reads back to the same table.
void expectRefusedOrFaithful(Writer write, const LensTable& t, const std::string& what) {
    std::string text;
    try {
        text = write(t);
    } catch (const LensTableError&) {
        return;
    }
    const LensTable again = parseLensTable(text, "again", TableLayout::GapAfter);
    expectSameRows(t, again, what);
    EXPECT_EQ(std::vector<std::string>(again.comments.begin(), again.comments.begin() + t.comments.size()), t.comments) << what;
    ADD_FAILURE() << what << " was written: the field's characters are not a file's line\n" << text.substr(0, 600);
}

// A comment, the name, a glass or a catalog holding a line break (or a character a reader may take for
// one) would start rows or keyword lines of its own: "UNIT IN", "MODE NSC", "SURF 99", a table row.
TEST(PrescriptionWriters, LineBreaksInAnyTextFieldAreRefusedNotWritten) {
    const std::vector<std::string> breaks = {"\n", "\r", "\v", "\f", "\x1b", "\xc2\x85", "\xe2\x80\xa8", "\xe2\x80\xa9", "\xff"};
    for (const std::string& b : breaks) {
        for (Writer write : {writeLensTableText, writeZemaxText}) {
            LensTable name = dgauss();
            name.comments = {"first" + b + "UNIT IN"};
            expectRefusedOrFaithful(write, name, "the first comment");
            LensTable note = dgauss();
            note.comments = {"first", "note" + b + "50 5 1.5 20"};
            expectRefusedOrFaithful(write, note, "a later comment");
            LensTable glass = dgauss();
            glass.rows[0].glass = "N-BK7" + b + "SURF 99";
            glass.rows[0].index = 0;
            expectRefusedOrFaithful(write, glass, "a glass name");
        }
        LensTable catalog = dgauss();
        catalog.catalogs = {"SCHOTT" + b + "MODE NSC"};
        EXPECT_THROW(writeZemaxText(catalog), LensTableError);
    }
}

TEST(PrescriptionWriters, NamesThatReadAsSomethingElseAreRefused) {
    LensTable abbe = dgauss();
    abbe.rows[0].glass = "64.17";  // a .dat's fifth column as a number is an Abbe number
    EXPECT_THROW(writeLensTableText(abbe), LensTableError);
    LensTable mirror = dgauss();
    mirror.rows[0].glass = "MIRROR";  // a .zmx GLAS MIRROR is a mirror
    EXPECT_THROW(writeZemaxText(mirror), LensTableError);
    LensTable spaced = dgauss();
    spaced.catalogs = {"SCHOTT OHARA"};
    EXPECT_THROW(writeZemaxText(spaced), LensTableError);
}

// A .dat is read at the d line: a lens designed at 550 nm written as a .dat would come back as
// another lens (EFL 49.0516 -> 49.2130 in issue 32). The .zmx holds it.
TEST(PrescriptionWriters, ADatRefusesAPrimaryWavelengthAZmxKeepsIt) {
    const LensTable glasses = withGapAfterRows(readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-glass.dat"));
    LensTable t = glasses;
    t.primaryWavelength = 550;
    try {
        writeLensTableText(t);
        FAIL() << "a 550 nm lens was written as a .dat";
    } catch (const LensTableError& e) {
        EXPECT_NE(e.problem().find("550"), std::string::npos) << e.problem();
        EXPECT_NE(e.problem().find(".zmx"), std::string::npos) << e.problem();
    }
    const LensTable again = parseLensTable(writeZemaxText(t), "again.zmx");
    EXPECT_EQ(again.primaryWavelength, 550);
    EXPECT_NEAR(efl(again), efl(t), 1e-12 * efl(t));
    EXPECT_GT(std::fabs(efl(t) - efl(glasses)), 1e-3) << "550 nm and the d line must give different lenses";
}

// PWAV names the primary wherever it is in the list, or in a list that lacked it.
TEST(PrescriptionWriters, AZmxNamesItsPrimaryWavelengthWhereverItIs) {
    struct Case {
        std::vector<double> list;
        double primary;
    };
    for (const Case& c : {Case{{kWavelengthF, kWavelengthD, kWavelengthC}, kWavelengthC}, Case{{kWavelengthF, kWavelengthD}, 550},
                          Case{{}, 550}, Case{{}, kWavelengthD}, Case{{kWavelengthC, kWavelengthD}, kWavelengthD}}) {
        LensTable t = dgauss();
        t.wavelengths = c.list;
        t.primaryWavelength = c.primary;
        const LensTable again = parseLensTable(writeZemaxText(t), "again.zmx");
        EXPECT_EQ(again.primaryWavelength, c.primary) << c.list.size() << " listed";
        for (double nm : c.list) EXPECT_NE(std::find(again.wavelengths.begin(), again.wavelengths.end(), nm), again.wavelengths.end());
    }
}

TEST(PrescriptionWriters, AZmxRefusesWavelengthsLenslabCannotTrace) {
    for (double nm : {-500.0, 0.0, 100.0, 3000.0}) {
        LensTable t = dgauss();
        t.wavelengths = {kWavelengthD, nm};
        EXPECT_THROW(writeZemaxText(t), LensTableError) << nm;
    }
}

// The catalog order (GCAT, or a row's own catalog) decides between makers' glasses of one name; a .dat has none, so it refuses
// a lens whose glass the order decides, and writes one where it does not matter.
TEST(PrescriptionWriters, ADatRefusesACatalogOrderThatPicksTheGlass) {
    std::optional<std::pair<std::string, std::string>> decided;  // a name and the maker that changes it
    for (const Medium& g : catalogGlasses()) {
        for (const std::string& maker : glassCatalogNames()) {
            const GlassLookup with = findGlass(g.name, {maker}), without = findGlass(g.name);
            if (with.glass && without.glass && with.glass->catalog != without.glass->catalog) decided = {{g.name, maker}};
            if (decided) break;
        }
        if (decided) break;
    }
    ASSERT_TRUE(decided) << "no glass name found in two catalogs";
    LensTable t = dgauss();
    t.rows[0].glass = decided->first;
    t.rows[0].index = 0;
    t.catalogs = {decided->second};
    EXPECT_THROW(writeLensTableText(t), LensTableError) << decided->first << " via " << decided->second;
    t.catalogs = {findGlass(decided->first).glass->catalog};
    EXPECT_NO_THROW(writeLensTableText(t)) << "the default order's own maker first changes nothing";
    // The row's own catalog (Code V's NAME_MAKER) decides it the same way.
    t.catalogs.clear();
    t.rows[0].glassCatalog = decided->second;
    EXPECT_THROW(writeLensTableText(t), LensTableError) << decided->first << "_" << decided->second;
}

// lenslab's own column header is written once, however often a lens is saved: it used to pile up
// one comment a save, and the 62nd save was refused (64 comments at most).
TEST(PrescriptionWriters, SavingADatAgainAndAgainKeepsOneHeader) {
    LensTable t = dgauss();
    const std::string first = writeLensTableText(t);
    std::string text = first;
    for (int save = 0; save < 70; ++save) text = writeLensTableText(parseLensTable(text, "saved.dat", TableLayout::GapAfter));
    EXPECT_EQ(text, first);
}

// Radii through a .zmx (curvatures) come back as the same doubles, the awkward ones too: 1 / (1 / r)
// in doubles is one ulp off for about a quarter of radii near 1 mm.
TEST(PrescriptionWriters, ZemaxRadiiRoundTripExactly) {
    LensTable t = dgauss();
    std::uint64_t state = 12345;
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        for (LensTableRow& row : t.rows) {
            if (row.radius == 0) continue;
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double unit = double(state >> 11) / double(1ull << 53);  // [0, 1)
            row.radius = std::copysign(std::pow(10.0, 6 * unit - 2), row.radius);  // 0.01 mm to 10 m
        }
        const LensTable again = parseLensTable(writeZemaxText(t), "again.zmx");
        for (std::size_t i = 0; i < t.rows.size(); ++i) {
            ASSERT_EQ(again.rows[i].radius, t.rows[i].radius) << "row " << i + 1 << " trial " << trial;
            ++checked;
        }
    }
    EXPECT_GT(checked, 2000);
}

// The editor's JSON is checked at the door, as files are when read: bounded names and text on one
// line, wavelengths lenslab traces; a glass name of a megabyte is refused before any catalog search
// (the nearest-name search over it took 27 s).
TEST(PrescriptionJson, NamesTextAndWavelengthsAreCheckedAtTheDoor) {
    const nlohmann::json good = prescriptionJson(dgauss());
    const auto refused = [&](const std::function<void(nlohmann::json&)>& change, const std::string& mentions) {
        nlohmann::json body = good;
        change(body);
        try {
            prescriptionFromJson(body, "edited");
            ADD_FAILURE() << "accepted; expected a refusal mentioning " << mentions;
        } catch (const LensTableError& e) {
            EXPECT_NE(e.problem().find(mentions), std::string::npos) << e.problem();
            EXPECT_LT(e.problem().size(), 200u) << "the problem echoes the input";
        }
    };
    refused([](auto& b) { b["comments"] = {"a\nUNIT IN"}; }, "comment 1");
    refused([](auto& b) { b["comments"] = {"a", "b\vc"}; }, "comment 2");
    refused([](auto& b) { b["comments"] = std::vector<std::string>(2, std::string(3000, 'x')); }, "4096");
    refused([](auto& b) { b["catalogs"] = {"SCHOTT\nMODE NSC"}; }, "catalog");
    refused([](auto& b) { b["wavelengths_nm"] = {587.5618, -500}; }, "-500 nm");
    refused([](auto& b) { b["primary_wavelength_nm"] = 100; }, "100 nm");
    refused([](auto& b) { b["rows"][1]["glass"] = "N-BK7\nSURF 99"; }, "glass");
    const auto start = std::chrono::steady_clock::now();
    refused([](auto& b) { b["rows"][1]["glass"] = std::string(1 << 20, 'Q'); }, "1048576 characters");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    EXPECT_NO_THROW(prescriptionFromJson(good, "edited"));
}

}  // namespace
}  // namespace lenslab
