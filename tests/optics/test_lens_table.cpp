// The lens-table parser: both layouts, line endings, comments, and every error with its message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"
#include "trace/ExactTrace.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

// Expects parsing + building to fail with a message naming file, line and problem.
void expectTableError(const std::string& text, int line, const std::string& part,
                      std::optional<TableLayout> layout = std::nullopt) {
    expectReadError([&] { buildLensSystem(parseLensTable(text, "bad.dat", layout)); }, text, "bad.dat", line, part);
}

const char* kGapBefore =
    "# a simple doublet with a stop\n"
    "50 0 1.5 20\n"
    "-50 5 1 20\n"
    "0 5 0 10\n"
    "40 5 1.6 18\n"
    "-80 4 1 18\n";

}  // namespace

TEST(LensTable, ReadsGapBeforeLayout) {
    const LensSystem lens = buildLensSystem(parseLensTable(kGapBefore, "t.dat"));
    ASSERT_EQ(lens.surfaces.size(), 5u);
    EXPECT_EQ(lens.layout, TableLayout::GapBefore);
    EXPECT_DOUBLE_EQ(lens.surfaces[0].z, 0);
    EXPECT_DOUBLE_EQ(lens.surfaces[1].z, -5);
    EXPECT_DOUBLE_EQ(lens.surfaces[2].z, -10);
    EXPECT_DOUBLE_EQ(lens.surfaces[4].z, -19);
    EXPECT_EQ(lens.stopIndex, 2);
    EXPECT_DOUBLE_EQ(lens.surfaces[0].indexAfter, 1.5);
    EXPECT_DOUBLE_EQ(lens.surfaces[2].indexAfter, 1.0);  // N 0 is air
    EXPECT_DOUBLE_EQ(lens.surfaces[0].apertureRadius, 10);  // the column is a diameter
    EXPECT_EQ(lens.surfaces[1].line, 3);
    EXPECT_EQ(lens.comments.at(0), "a simple doublet with a stop");
}

TEST(LensTable, ReadsGapAfterLayoutWithTheSameGeometry) {
    const char* gapAfter = "50 5 1.5 20\n-50 5 1 20\n0 5 0 10\n40 4 1.6 18\n-80 0 1 18";
    const LensSystem a = buildLensSystem(parseLensTable(kGapBefore, "a.dat"));
    const LensSystem b = buildLensSystem(parseLensTable(gapAfter, "b.dat"));
    EXPECT_EQ(b.layout, TableLayout::GapAfter);
    ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) EXPECT_DOUBLE_EQ(a.surfaces[i].z, b.surfaces[i].z);
}

TEST(LensTable, CopesWithCrlfTabsCommentsAndNoFinalNewline) {
    const std::string text = "# header\r\n  50\t0 \t1.5\t20 # trailing comment\r\n\r\n-50 5 1 20\r\n0\t5\t0\t10\r\n40 5 1.6 18\r\n-80\t4\t1\t18.5";
    const LensSystem lens = buildLensSystem(parseLensTable(text, "crlf.dat"));
    ASSERT_EQ(lens.surfaces.size(), 5u);
    EXPECT_DOUBLE_EQ(lens.surfaces.back().apertureRadius, 9.25);  // the last value is kept
    EXPECT_EQ(lens.surfaces.back().line, 7);
}

TEST(LensTable, ExplicitLayoutOverridesDetection) {
    // First and last gap both 0: ambiguous unless told.
    const char* both = "50 0 1.5 20\n-50 5 1 20\n0 5 0 10\n40 5 1.6 18\n-80 0 1 18\n";
    expectTableError(both, 1, "ambiguous layout");
    const LensTable t = parseLensTable(both, "both.dat", TableLayout::GapAfter);
    EXPECT_EQ(t.layout, TableLayout::GapAfter);
    EXPECT_FALSE(t.layoutDetected);
    expectTableError("50 3 1.5 20\n-50 5 1 20\n0 5 0 10\n40 5 1.6 18\n-80 2 1 18\n", 1, "gap-before layout needs",
                TableLayout::GapBefore);
}

TEST(LensTable, FlatRefractingSurfaceIsNotAStop) {
    const LensSystem lens = buildLensSystem(parseLensTable("0 0 1.5 20\n-50 5 1 20\n0 5 0 10\n-80 4 1 18\n", "flat.dat"));
    EXPECT_FALSE(lens.surfaces[0].isStop);
    EXPECT_DOUBLE_EQ(lens.surfaces[0].curvature, 0);
    EXPECT_EQ(lens.stopIndex, 2);
}

TEST(LensTableErrors, WrongColumnCount) {
    expectTableError("50 0 1.5\n", 1, "expected 4 or 5 columns (radius, gap, N, diameter, optional glass or Vd), found 3");
}
TEST(LensTableErrors, TooManyColumns) { expectTableError("50 0 1.5 20\n-50 5 1.6 20 7 8\n", 2, "found 6"); }

// The optional fifth column: a number is the glass's Abbe number Vd, anything else its catalog name.
TEST(LensTable, FifthColumnNamesTheGlass) {
    const LensTable t = parseLensTable("50 0 1.5168 20 64.17\n-50 5 1.6477 20 SF2\n-80 1 1 20\n0 5 0 10\n", "glass.dat");
    EXPECT_DOUBLE_EQ(t.rows[0].abbe, 64.17);
    EXPECT_EQ(t.rows[0].glass, "");
    EXPECT_EQ(t.rows[1].glass, "SF2");
    EXPECT_EQ(t.rows[1].abbe, 0);
    EXPECT_DOUBLE_EQ(t.rows[1].index, 1.6477);  // N stays column 3
    EXPECT_EQ(t.rows[2].glass, "");
    EXPECT_EQ(t.format, "table");
    EXPECT_TRUE(t.rows[3].stop);
    EXPECT_EQ(buildLensSystem(t).surfaces.size(), 4u);
}
TEST(LensTableErrors, AbbeNumberNotPositive) {
    expectTableError("50 0 1.5 20 0\n", 1, "Abbe number Vd must be positive, found 0");
    expectTableError("50 0 1.5 20 -30\n", 1, "Abbe number Vd must be positive, found -30");
}
TEST(LensTableErrors, AbbeNumberNotFinite) { expectTableError("50 0 1.5 20 inf\n", 1, "column 5 (glass or Vd) is not a finite number"); }
TEST(LensTableErrors, FifthColumnOnAir) { expectTableError("50 0 1.5 20\n-50 5 1 20 60\n", 2, "on an air or stop row"); }
TEST(LensTableErrors, FifthColumnOnStop) { expectTableError("50 0 1.5 20\n0 5 0 10 N-BK7\n", 2, "on an air or stop row"); }
TEST(LensTableErrors, NotANumber) { expectTableError("50 0 1.5 20\n-50 five 1 20\n", 2, "column 2 (gap) is not a finite number: 'five'"); }
TEST(LensTableErrors, NotFinite) { expectTableError("50 0 1.5 20\n-50 5 1 nan\n", 2, "column 4 (diameter) is not a finite number"); }
TEST(LensTableErrors, NegativeDiameter) { expectTableError("50 0 1.5 -20\n", 1, "diameter must be positive"); }
TEST(LensTableErrors, ZeroDiameter) { expectTableError("50 0 1.5 20\n0 5 0 0\n", 2, "diameter must be positive"); }
TEST(LensTableErrors, NegativeGap) { expectTableError("50 0 1.5 20\n-50 -5 1 20\n", 2, "negative gap"); }
TEST(LensTableErrors, IndexBelowOne) { expectTableError("50 0 0.8 20\n", 1, "is below 1"); }
TEST(LensTableErrors, Empty) { expectTableError("# only a comment\n\n", 2, "no surfaces"); }
TEST(LensTableErrors, NoStop) { expectTableError("50 0 1.5 20\n-50 5 1 20\n", 1, "no aperture stop"); }
TEST(LensTableErrors, TwoStops) {
    expectTableError("50 0 1.5 20\n-50 5 1 20\n0 5 0 10\n0 5 0 10\n-80 4 1 18\n", 4, "a second aperture stop");
}
TEST(LensTableErrors, DiameterLargerThanSphere) {
    expectTableError("8 0 1.5 20\n-50 5 1 20\n0 5 0 10\n", 1, "larger than the sphere of radius 8 mm allows");
}
// Two strongly convex-toward-each-other surfaces 1 mm apart at the axis cross near the rim: the
// lens reads, with a warning naming both lines and the height, and both apertures end there.
TEST(LensTable, OverlappingEdgesWarnAndClip) {
    const LensSystem lens = buildLensSystem(parseLensTable("50 0 1.5 20\n-20 1 1 20\n0 5 0 10\n", "edge.dat"));
    // Where 50 - sqrt(50^2 - h^2) + 20 - sqrt(20^2 - h^2) = 1: bisected here on the closed form.
    double lo = 0, hi = 10;
    for (int i = 0; i < 200; ++i) {
        const double h = 0.5 * (lo + hi);
        (50 - std::sqrt(2500 - h * h) + 20 - std::sqrt(400 - h * h) < 1 ? lo : hi) = h;
    }
    ASSERT_EQ(lens.warnings.size(), 1u);
    EXPECT_EQ(lens.warnings[0].line, 2);
    const std::string& w = lens.warnings[0].message;
    EXPECT_NE(w.find("lines 1 and 2"), std::string::npos) << w;
    char height[32];
    std::snprintf(height, sizeof height, "%.6g mm", lo);
    EXPECT_NE(w.find(std::string("cross at height ") + height), std::string::npos) << w;
    // The builder lets surfaces touch within 1e-9 mm (rounding): the crossing moves by that over the slope.
    EXPECT_NEAR(lens.surfaces[0].apertureRadius, lo, 1e-8);
    EXPECT_NEAR(lens.surfaces[1].apertureRadius, lo, 1e-8);
    // A ray beyond the crossing is clipped where the two solids would cut into each other.
    EXPECT_EQ(traceRay(lens, {{0, lo + 0.05, 5}, {0, 0, -1}}, TraceDirection::SceneToFilm).blocked,
              BlockReason::OutsideAperture);
}
TEST(LensTableErrors, AmbiguousLayoutWithoutZeroGaps) {
    expectTableError("50 2 1.5 20\n-50 5 1 20\n0 5 0 10\n", 1, "cannot tell the layout");
}
TEST(LensTableErrors, LastSurfaceInGlass) { expectTableError("50 0 1.5 20\n0 5 0 10\n-50 5 1.5 20\n", 3, "must leave the ray in air"); }
TEST(LensTableErrors, UnreadableFile) {
    try {
        readLensTable("/nonexistent/lens.dat");
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/lens.dat: cannot open the file");
    }
}

// The project's tables load, and their first-order figures are those published for them
// (lenses/published-figures.tsv names each source).
TEST(LensTable, BundledTablesMatchThePublishedFigures) {
    const std::string dir = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
    std::ifstream figures(dir + "published-figures.tsv");
    ASSERT_TRUE(figures) << "no " << dir << "published-figures.tsv";
    std::set<std::string> lenses;
    int checked = 0;
    for (std::string line; std::getline(figures, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        std::string lens, figure;
        double value = 0, tolerance = 0;
        ASSERT_TRUE(row >> lens >> figure >> value >> tolerance) << line;
        const std::string table = dir + lens + ".dat";
        const LensSystem l = loadLensSystem(std::filesystem::exists(table) ? table : dir + lens + ".zmx");
        const FirstOrder fo = computeFirstOrder(l);
        const double computed = figure == "efl" ? fo.efl : figure == "bfd" ? l.rearZ() - fo.zFPrime : fo.zPPrime - l.rearZ();
        ASSERT_TRUE(figure == "efl" || figure == "bfd" || figure == "pprime") << line;
        EXPECT_NEAR(computed, value, tolerance) << lens << " " << figure;
        lenses.insert(lens);
        ++checked;
    }
    EXPECT_EQ(checked, 18);
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".dat" || e.path().extension() == ".zmx") {
            EXPECT_TRUE(lenses.count(e.path().stem().string())) << e.path() << " has no published figure";
        }
}

namespace {

// n rows of alternating thin air gaps and glass, gap-before (first gap 0).
std::string manySurfaces(int n) {
    std::string t;
    for (int i = 0; i < n; ++i) t += std::string(i % 2 ? "-500" : "500") + (i ? " 0.5 " : " 0 ") + (i % 2 ? "1" : "1.5") + " 20\n";
    return t;
}

}  // namespace

TEST(LensTable, RefusesTablesBeyondTheSurfaceLimitAtTheFirstRowTooMany) {
    EXPECT_EQ(parseLensTable(manySurfaces(kMaxLensSurfaces), "big.dat").rows.size(), std::size_t(kMaxLensSurfaces));
    // Row 257 is the first one refused: the message names its line and the limit.
    expectTableError(manySurfaces(10000), kMaxLensSurfaces + 1, "too many surfaces: a lens table may have at most 256 rows");
}
