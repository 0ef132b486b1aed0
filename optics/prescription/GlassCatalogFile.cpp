#include "prescription/GlassCatalogFile.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "prescription/GlassCatalog.h"
#include "prescription/LensTable.h"
#include "prescription/NumberText.h"
#include "prescription/TextEncoding.h"

namespace lenslab {

namespace {

// A catalog has a few thousand glasses at most; a bound keeps an upload from holding millions.
constexpr std::size_t kMaxGlasses = 20000;
// Makers' glass and catalog names are a dozen characters; a bound keeps a name from being megabytes
// in every lookup, list and message.
constexpr std::size_t kMaxNameLength = 64;

std::string catalogName(const std::string& fileName) {
    std::string base = fileName.substr(fileName.find_last_of("/\\") + 1);
    if (isGlassCatalogFileName(base)) base.resize(base.size() - 4);
    return upperCase(base);
}

struct AgfReader {
    std::string file;
    [[noreturn]] void fail(int line, const std::string& problem) const { throw LensTableError(file, line, problem); }

    double number(const std::vector<std::string>& f, std::size_t i, int line, const char* what) const {
        if (i >= f.size()) fail(line, std::string(what) + " is missing");
        char* end = nullptr;
        const double v = std::strtod(f[i].c_str(), &end);
        if (end == f[i].c_str() || *end != '\0' || !std::isfinite(v))
            fail(line, std::string(what) + " is not a finite number: '" + f[i].substr(0, 40) + "'");
        return v;
    }
};

// Zemax's formula number's (1 to 13) coefficients in Medium's layout (Medium.h).
void setFormula(Medium& m, int formula, const std::array<double, 10>& a) {
    auto& c = m.coefficients;
    c = {};
    switch (formula) {
        case 1:  // Schott
        case 10:  // Extended
            m.formula = DispersionFormula::SchottPolynomial;
            c[0] = a[0], c[1] = a[1], c[3] = a[2], c[4] = a[3], c[5] = a[4], c[6] = a[5];
            if (formula == 10) c[7] = a[6], c[8] = a[7];
            return;
        case 12:  // Extended 2
            m.formula = DispersionFormula::SchottPolynomial;
            c[0] = a[0], c[1] = a[1], c[3] = a[2], c[4] = a[3], c[5] = a[4], c[6] = a[5], c[2] = a[6], c[9] = a[7];
            return;
        case 13:  // Extended 3
            m.formula = DispersionFormula::SchottPolynomial;
            for (int i = 0; i < 9; ++i) c[i] = a[i];
            return;
        case 2: case 6: case 11: {  // Sellmeier 1, 3, 5: 3, 4, 5 terms
            m.formula = DispersionFormula::Sellmeier;
            const int terms = formula == 2 ? 3 : formula == 6 ? 4 : 5;
            for (int i = 0; i < 2 * terms; ++i) c[1 + i] = a[i];
            return;
        }
        case 9:  // Sellmeier 4: n^2 = A + ..., Medium's Sellmeier has 1 + A
            m.formula = DispersionFormula::Sellmeier;
            c[0] = a[0] - 1, c[1] = a[1], c[2] = a[2], c[3] = a[3], c[4] = a[4];
            return;
        case 3: m.formula = DispersionFormula::Herzberger; break;
        case 4: m.formula = DispersionFormula::SellmeierTwo; break;
        case 5: m.formula = DispersionFormula::Conrady; break;
        case 7: m.formula = DispersionFormula::HandbookOne; break;
        default: m.formula = DispersionFormula::HandbookTwo; break;  // 8
    }
    for (int i = 0; i < 6; ++i) c[i] = a[i];
}

std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string w; in >> w;) f.push_back(w);
    return f;
}

}  // namespace

bool isGlassCatalogFileName(const std::string& name) {
    return name.size() > 4 && upperCase(name.substr(name.size() - 4)) == ".AGF";
}

GlassCatalogFile parseGlassCatalogFile(const std::string& bytes, const std::string& fileName) {
    AgfReader r{fileName};
    GlassCatalogFile catalog;
    catalog.name = catalogName(fileName);
    if (catalog.name.size() > kMaxNameLength)
        r.fail(0, "the catalog's name (the file name without .agf) has " + std::to_string(catalog.name.size()) +
                      " characters, more than " + std::to_string(kMaxNameLength));
    std::map<std::string, int> nameLines;  // each glass's name in upper case (as looked up), and its NM line
    std::istringstream in(toUtf8Text(bytes, fileName));
    int lineNo = 0;
    int formula = 0, nameLine = 0;
    bool haveCoefficients = false;
    auto finish = [&] {
        if (catalog.glasses.empty()) return;
        if (!haveCoefficients) r.fail(nameLine, "glass " + catalog.glasses.back().name + " has no CD line (its coefficients)");
    };
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::vector<std::string> f = fields(line);
        if (f.empty()) continue;
        const std::string& key = f[0];
        if (key == "NM") {
            finish();
            if (catalog.glasses.size() == kMaxGlasses)
                r.fail(lineNo, "more than " + std::to_string(kMaxGlasses) + " glasses in one catalog");
            if (f.size() < 6) r.fail(lineNo, "NM needs a name, a formula number, a code, nd and Vd");
            if (f[1].size() > kMaxNameLength)
                r.fail(lineNo, "the glass name has " + std::to_string(f[1].size()) + " characters, more than " +
                                   std::to_string(kMaxNameLength));
            if (const auto [first, added] = nameLines.emplace(glassNameKey(f[1]), lineNo); !added)
                r.fail(lineNo, "glass " + f[1] + " is named twice in the catalog: first on line " +
                                   std::to_string(first->second) + "; a lens could find only one of them");
            Medium glass;
            glass.name = f[1];
            glass.catalog = catalog.name;
            const double number = r.number(f, 2, lineNo, "the formula number");
            if (number != std::floor(number) || number < 1 || number > 13)
                r.fail(lineNo, "formula number " + f[2] + " of glass " + f[1] + " is not one of Zemax's 1 to 13");
            formula = static_cast<int>(number);
            glass.nd = r.number(f, 4, lineNo, "nd");
            glass.vd = r.number(f, 5, lineNo, "Vd");
            if (!(glass.nd >= 1)) r.fail(lineNo, "nd " + f[4] + " of glass " + f[1] + " is below 1");
            catalog.glasses.push_back(glass);
            catalog.formulaNumbers.push_back(formula);
            nameLine = lineNo;
            haveCoefficients = false;
        } else if (key == "CD" || key == "LD") {
            if (catalog.glasses.empty()) r.fail(lineNo, key + " before the first NM line: it belongs to a glass");
            Medium& glass = catalog.glasses.back();
            if (key == "LD") {
                glass.minNm = 1000 * r.number(f, 1, lineNo, "LD's shortest wavelength");
                glass.maxNm = 1000 * r.number(f, 2, lineNo, "LD's longest wavelength");
                if (!(glass.minNm > 0 && glass.maxNm > glass.minNm))
                    r.fail(lineNo, "LD " + f[1] + " " + f[2] + " is not a wavelength range in micrometres");
                continue;
            }
            std::array<double, 10> a{};
            for (std::size_t i = 1; i < f.size() && i <= a.size(); ++i) a[i - 1] = r.number(f, i, lineNo, "a CD coefficient");
            setFormula(glass, formula, a);
            haveCoefficients = true;
            const double nd = refractiveIndex(glass, kWavelengthD);
            if (!(std::isfinite(nd) && nd > 0))
                r.fail(lineNo, "glass " + glass.name + "'s formula has no index at the d line");
        }
        // CC, GC, ED, TD, OD, IT and anything newer: facts lenslab does not use.
    }
    finish();
    if (catalog.glasses.empty()) r.fail(std::max(lineNo, 1), "no glasses: an AGF catalog lists each glass on an NM line");
    return catalog;
}

GlassCatalogFile readGlassCatalogFile(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw LensTableError(path, 0, "cannot open the file");
    std::ostringstream ss;
    ss << f.rdbuf();
    if (f.bad()) throw LensTableError(path, 0, "cannot read the file");
    return parseGlassCatalogFile(ss.str(), path);
}

}  // namespace lenslab
