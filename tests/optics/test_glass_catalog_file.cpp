// Zemax glass catalogs (.agf): glasses of every dispersion formula the makers use, written out in
// the AGF layout from the makers' own coefficients (the bundled catalog's, which come from their
// Zemax catalogs), read back and checked against the makers' printed nd and Vd; every other formula
// against its closed form; the catalogs searched before the bundled one; refusals with file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "prescription/GlassCatalog.h"
#include "prescription/GlassCatalogFile.h"
#include "prescription/LensSystem.h"
#include "prescription/RowMedium.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

// The makers' formulas in the bundled catalog, as Zemax numbers them, with each one's CD layout.
struct FormulaLayout {
    int number;
    std::vector<int> mediumIndex;  // CD value i is Medium coefficient mediumIndex[i] (-1: not used)
};

// Sellmeier 1 (3 terms) and 3 (4 terms): K1 L1 K2 L2 ...; Schott: a0 a1 a2 .. a5 (L^2, L^-2 ..);
// Extended: Schott + a6 L^-10 a7 L^-12; Extended 3: a0 a1 (L^2) a2 (L^4) a3 .. a8 (L^-2 .. L^-12).
const FormulaLayout kSellmeier1{2, {1, 2, 3, 4, 5, 6}};
const FormulaLayout kSellmeier3{6, {1, 2, 3, 4, 5, 6, 7, 8}};
const FormulaLayout kSchott{1, {0, 1, 3, 4, 5, 6}};
const FormulaLayout kExtended{10, {0, 1, 3, 4, 5, 6, 7, 8}};
const FormulaLayout kExtended3{13, {0, 1, 2, 3, 4, 5, 6, 7, 8}};

// Which layout writes a bundled glass exactly (nullptr: none of these).
const FormulaLayout* layoutOf(const Medium& g) {
    const auto& c = g.coefficients;
    if (g.formula == DispersionFormula::Sellmeier) {
        if (c[0] != 0 || c[9] != 0 || c[10] != 0) return nullptr;
        return c[7] == 0 && c[8] == 0 ? &kSellmeier1 : &kSellmeier3;
    }
    if (g.formula != DispersionFormula::SchottPolynomial || c[9] != 0) return nullptr;
    if (c[2] != 0) return &kExtended3;
    return c[7] == 0 && c[8] == 0 ? &kSchott : &kExtended;
}

std::string agfLine(const Medium& g, const FormulaLayout& f) {
    std::ostringstream s;
    s.precision(17);
    s << "NM " << g.name << " " << f.number << " 000000 " << g.nd << " " << g.vd << " 0 1\r\n";
    s << "ED 7.1 8.3 2.51 -0.0009 0\r\nCD";
    for (int i : f.mediumIndex) s << " " << g.coefficients[i];
    s << "\r\nTD 0 0 0 0 0 0 20\r\nLD " << g.minNm / 1000 << " " << g.maxNm / 1000 << "\r\n";
    return s.str();
}

void expectAgfError(const std::string& text, int line, const std::string& part) {
    expectReadError([&] { parseGlassCatalogFile(text, "bad.agf"); }, text, "bad.agf", line, part);
}

}  // namespace

// Up to ten glasses of each formula the makers' catalogs use, by maker, read back from AGF text:
// the index matches the maker's formula everywhere and the printed nd and Vd at the d line.
TEST(GlassCatalogFile, MakersGlassesOfEveryFormulaTheyUseReadBack) {
    std::map<int, std::vector<const Medium*>> chosen;
    for (const Medium& g : catalogGlasses()) {
        const FormulaLayout* f = layoutOf(g);
        if (f && chosen[f->number].size() < 10 && g.catalog != "MISC") chosen[f->number].push_back(&g);
    }
    ASSERT_EQ(chosen.size(), 5u);  // Sellmeier 1 and 3, Schott, Extended, Extended 3
    for (const auto& [number, glasses] : chosen) {
        EXPECT_GE(glasses.size(), number == 6 ? 7u : 10u) << "formula " << number;
        std::string text = "CC lenslab test catalog\r\n";
        for (const Medium* g : glasses) text += agfLine(*g, *layoutOf(*g));
        const GlassCatalogFile read = parseGlassCatalogFile(text, "/some/folder/Maker.agf");
        EXPECT_EQ(read.name, "MAKER");
        ASSERT_EQ(read.glasses.size(), glasses.size());
        for (std::size_t i = 0; i < glasses.size(); ++i) {
            const Medium &g = *glasses[i], &r = read.glasses[i];
            EXPECT_EQ(r.name, g.name);
            EXPECT_EQ(r.catalog, "MAKER");
            for (double nm : {400.0, 486.1327, 587.5618, 656.2725, 800.0})
                EXPECT_NEAR(refractiveIndex(r, nm), refractiveIndex(g, nm), 1e-13) << g.name << " " << nm;
            EXPECT_NEAR(refractiveIndex(r, kWavelengthD), g.nd, 3e-5) << g.catalog << " " << g.name << " formula " << number;
            EXPECT_NEAR(abbeNumber(r), g.vd, 0.1) << g.catalog << " " << g.name << " formula " << number;
            EXPECT_DOUBLE_EQ(r.minNm, g.minNm);
        }
    }
}

// The formulas no bundled glass uses, against their closed forms (Zemax's manual), L in micrometres.
TEST(GlassCatalogFile, EveryOtherFormulaAgainstItsClosedForm) {
    const std::string text =
        "NM HERZ 3 0 1.6 50 0 1\nCD 1.58 0.006 -0.0004 -0.002 1e-5 -2e-7\n"
        "NM SELL2 4 0 1.5 60 0 1\nCD 0.2 1.0 0.09 0.02 10.3\n"
        "NM CONR 5 0 1.5 60 0 1\nCD 1.49 0.004 0.0002\n"
        "NM HB1 7 0 1.5 60 0 1\nCD 2.27 0.011 0.01 0.01\n"
        "NM HB2 8 0 1.5 60 0 1\nCD 1.3 0.95 0.011 0.01\n"
        "NM SELL4 9 0 1.5 60 0 1\nCD 1.2 1.1 0.01 0.9 100\n"
        "NM SELL5 11 0 1.5 60 0 1\nCD 0.5 0.004 0.4 0.02 0.2 0.05 0.1 80 0.05 120\n"
        "NM EXT2 12 0 1.5 60 0 1\nCD 2.27 -0.01 0.011 2e-4 -1e-5 6e-7 1e-4 -1e-6\n";
    const GlassCatalogFile c = parseGlassCatalogFile(text, "OTHER.AGF");
    ASSERT_EQ(c.glasses.size(), 8u);
    for (double nm : {420.0, 587.5618, 760.0}) {
        const double l = nm / 1000, x = l * l;
        const double m = 1 / (x - 0.028);
        const double expected[8] = {
            1.58 + 0.006 * m - 0.0004 * m * m - 0.002 * x + 1e-5 * x * x - 2e-7 * x * x * x,
            std::sqrt(1 + 0.2 + 1.0 * x / (x - 0.09 * 0.09) + 0.02 / (x - 10.3 * 10.3)),
            1.49 + 0.004 / l + 0.0002 / std::pow(l, 3.5),
            std::sqrt(2.27 + 0.011 / (x - 0.01) - 0.01 * x),
            std::sqrt(1.3 + 0.95 * x / (x - 0.011) - 0.01 * x),
            std::sqrt(1.2 + 1.1 * x / (x - 0.01) + 0.9 * x / (x - 100)),
            std::sqrt(1 + 0.5 * x / (x - 0.004) + 0.4 * x / (x - 0.02) + 0.2 * x / (x - 0.05) + 0.1 * x / (x - 80) +
                      0.05 * x / (x - 120)),
            std::sqrt(2.27 - 0.01 * x + 0.011 / x + 2e-4 / (x * x) - 1e-5 / (x * x * x) + 6e-7 / (x * x * x * x) +
                      1e-4 * x * x - 1e-6 * x * x * x)};
        for (int i = 0; i < 8; ++i) EXPECT_NEAR(refractiveIndex(c.glasses[i], nm), expected[i], 1e-14) << c.glasses[i].name << " " << nm;
    }
}

// A loaded catalog is searched before the bundled makers; a prescription's own catalog (GCAT, or
// the catalog beside a Code V glass name) before both.
TEST(GlassCatalogFile, LoadedCatalogsAreSearchedFirst) {
    Medium mine = constantIndex(1.7);
    mine.name = "N-BK7";
    Medium special = constantIndex(1.65);
    special.name = "SPECIAL-1";
    addGlassCatalog("MYGLASS", {mine, special});
    EXPECT_EQ(loadedGlassCatalogNames(), (std::vector<std::string>{"MYGLASS"}));
    EXPECT_EQ(findGlass("N-BK7").glass->catalog, "MYGLASS");
    EXPECT_EQ(findGlass("N-BK7", {"SCHOTT"}).glass->catalog, "SCHOTT");
    EXPECT_EQ(findGlass("special 1").glass->nd, 1.65);
    const GlassLookup lookup = findGlass("N-BK7");
    EXPECT_EQ(lookup.searched.front(), "MYGLASS");
    clearLoadedGlassCatalogs();
    EXPECT_EQ(findGlass("N-BK7").glass->catalog, "SCHOTT");
    EXPECT_FALSE(findGlass("SPECIAL-1").glass);
}

// A catalog added after the bundled makers (the service's uploads) only adds names: a name the
// makers or an earlier catalog have keeps its glass, a GCAT line naming it does not move it forward,
// and it can be removed by name.
TEST(GlassCatalogFile, CatalogsAddedAfterTheMakersOnlyAddNames) {
    Medium mine = constantIndex(1.7);
    mine.name = "N-BK7";
    Medium special = constantIndex(1.65);
    special.name = "SPECIAL-1";
    addGlassCatalog("UPLOADED", {mine, special}, CatalogPrecedence::AfterBundled);
    Medium later = constantIndex(1.9);
    later.name = "SPECIAL-1";
    addGlassCatalog("LATER", {later}, CatalogPrecedence::AfterBundled);
    EXPECT_EQ(findGlass("N-BK7").glass->catalog, "SCHOTT");
    EXPECT_EQ(findGlass("N-BK7", {"UPLOADED"}).glass->catalog, "SCHOTT");
    EXPECT_EQ(findGlass("SPECIAL-1").glass->nd, 1.65);
    EXPECT_EQ(findGlass("SPECIAL-1", {"LATER"}).glass->nd, 1.65);
    EXPECT_EQ(findGlass("N-BK7").searched.back(), "LATER");
    EXPECT_TRUE(isGlassCatalogName("uploaded"));
    EXPECT_TRUE(isGlassCatalogName("Schott"));
    EXPECT_FALSE(isGlassCatalogName("NOSUCH"));
    EXPECT_EQ(loadedGlasses(CatalogPrecedence::AfterBundled).size(), 3u);
    EXPECT_TRUE(loadedGlasses(CatalogPrecedence::BeforeBundled).empty());
    const auto shadowed = shadowedGlassNames();
    EXPECT_EQ(shadowed.at("UPLOADED"), (std::vector<std::string>{"N-BK7"}));
    EXPECT_EQ(shadowed.at("LATER"), (std::vector<std::string>{"SPECIAL-1"}));
    EXPECT_TRUE(removeGlassCatalog("uploaded"));
    EXPECT_FALSE(removeGlassCatalog("UPLOADED"));
    EXPECT_EQ(findGlass("SPECIAL-1").glass->nd, 1.9);
    clearLoadedGlassCatalogs();
    EXPECT_FALSE(findGlass("SPECIAL-1").glass);
}

// A moulded variant no catalog has is read as its base glass, with a warning naming both.
TEST(GlassCatalogFile, MouldedVariantFallsBackToItsBaseGlassWithAWarning) {
    LensTable t;
    t.name = "m.zmx";
    t.format = "zmx";
    LensTableRow r;
    r.glass = "L-TIM28_MOLD";
    r.line = 12;
    std::vector<LensWarning> warnings;
    const Medium m = rowMedium(t, r, warnings);
    EXPECT_EQ(m.name, "L-TIM28");
    EXPECT_EQ(m.catalog, "OHARA");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].line, 12);
    EXPECT_NE(warnings[0].message.find("L-TIM28_MOLD"), std::string::npos);
    EXPECT_NE(warnings[0].message.find("L-TIM28 (OHARA)"), std::string::npos);
    EXPECT_EQ(mouldedBaseName("S-LAH64"), "");
    // The exact name comes first: a catalog that has the moulded glass gives it, without a warning.
    Medium moulded = constantIndex(1.68);
    moulded.name = "L-TIM28_MOLD";
    addGlassCatalog("MOULDED", {moulded});
    warnings.clear();
    EXPECT_EQ(rowMedium(t, r, warnings).nd, 1.68);
    EXPECT_TRUE(warnings.empty());
    clearLoadedGlassCatalogs();
    // An unknown glass is still refused by name, with the nearest names.
    r.glass = "L-TIM99_MOLD";
    try {
        rowMedium(t, r, warnings);
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 12);
        EXPECT_NE(e.problem().find("unknown glass 'L-TIM99_MOLD'"), std::string::npos) << e.what();
        EXPECT_NE(e.problem().find("nearest"), std::string::npos) << e.what();
    }
}

TEST(GlassCatalogFile, RefusalsNameTheLine) {
    expectAgfError("CC x\nCD 1 2 3\n", 2, "CD before the first NM");
    expectAgfError("NM G 14 0 1.5 60 0 1\nCD 1\n", 1, "formula number 14");
    expectAgfError("NM G 2 0 1.5 60 0 1\nLD 0.3 2.5\nNM H 2 0 1.5 60 0 1\nCD 1 0.01 0 0 0 0\n", 1, "has no CD line");
    expectAgfError("NM G 2 0 0.5 60 0 1\n", 1, "nd 0.5");
    expectAgfError("NM G 2 0 1.5\n", 1, "NM needs");
    expectAgfError("NM G 2 0 1.5 60 0 1\nCD 1 x\n", 2, "not a finite number");
    expectAgfError("NM G 2 0 1.5 60 0 1\nCD 1 0.01\nLD 2.5 0.3\n", 3, "not a wavelength range");
    expectAgfError("CC nothing here\n", 1, "no glasses");
    // Names the lookup cannot tell apart are one name: findGlass ignores case, spaces, underscores
    // and hyphens, so a lens naming N-BK7 could find only one of these.
    expectAgfError("NM N-BK7 2 0 1.5 60 0 1\nCD 1 0.01 0 0 0 0\nNM N_bk7 2 0 1.6 50 0 1\nCD 1 0.01 0 0 0 0\n", 3,
                   "glass N_bk7 is named twice in the catalog: first on line 1");
    EXPECT_TRUE(isGlassCatalogFileName("a/SCHOTT.AGF"));
    EXPECT_TRUE(isGlassCatalogFileName("hoya.agf"));
    EXPECT_FALSE(isGlassCatalogFileName("agf"));
}
