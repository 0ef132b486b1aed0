#include "prescription/RowMedium.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "prescription/GlassCatalog.h"
#include "prescription/NumberText.h"
#include "prescription/TextEncoding.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// The row's catalog, then the file's (Zemax GCAT), are searched first.
std::vector<std::string> preferredCatalogs(const LensTable& table, const std::string& rowCatalog) {
    std::vector<std::string> catalogs;
    if (!rowCatalog.empty()) catalogs.push_back(rowCatalog);
    catalogs.insert(catalogs.end(), table.catalogs.begin(), table.catalogs.end());
    return catalogs;
}

const GlassSubstitute* substituteFor(const LensTable& table, const std::string& name) {
    const std::string key = upperCase(name);
    for (const GlassSubstitute& s : table.substitutes)
        if (upperCase(s.name) == key) return &s;
    return nullptr;
}

[[noreturn]] void unknownGlass(const LensTable& table, const LensTableRow& r, const GlassLookup& found) {
    if (r.glass.size() > kMaxGlassNameLength)
        throw LensTableError(table.name, r.line, "a glass name of " + std::to_string(r.glass.size()) +
                                                     " characters: catalog names have at most " +
                                                     std::to_string(kMaxGlassNameLength));
    std::string msg = "unknown glass '" + r.glass + "' (searched " + joined(found.searched) + ")";
    if (!found.suggestions.empty()) msg += "; nearest: " + joined(found.suggestions);
    msg += "; give its nd and Vd instead to use a model glass, load its maker's catalog (an .agf file: --glass-catalog, or uploaded to the service), "
           "or name a substitute in a .smx file beside the prescription";
    throw LensTableError(table.name, r.line, msg);
}

Medium catalogMedium(const LensTable& table, const LensTableRow& r, std::vector<LensWarning>& warnings) {
    if (const GlassSubstitute* s = substituteFor(table, r.glass)) {
        if (s->medium) return *s->medium;
        const GlassLookup found = findGlass(s->glass, preferredCatalogs(table, s->catalog));
        if (!found.glass)
            throw LensTableError(table.name, r.line, s->source + " substitutes '" + s->glass + "' for '" + r.glass +
                                                         "', which no catalog has (searched " + joined(found.searched) + ")");
        return *found.glass;
    }
    const auto catalogs = preferredCatalogs(table, r.glassCatalog);
    const GlassLookup found = findGlass(r.glass, catalogs);
    if (found.glass) return *found.glass;
    const std::string base = mouldedBaseName(r.glass);
    if (!base.empty()) {
        const GlassLookup baseGlass = findGlass(base, catalogs);
        if (baseGlass.glass) {
            warnings.push_back({r.line, "glass " + r.glass + " (a moulded variant) is not in the catalogs: " +
                                            baseGlass.glass->name + " (" + baseGlass.glass->catalog +
                                            "), its base glass, is used instead"});
            return *baseGlass.glass;
        }
    }
    unknownGlass(table, r, found);
}

}  // namespace

std::string mouldedBaseName(const std::string& name) {
    const std::string key = upperCase(name);
    for (const char* suffix : {"_MOLD", "-MOLD", " MOLD", "_MOLDED", "-MOLDED"}) {
        const std::string s = suffix;
        if (key.size() > s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0)
            return name.substr(0, name.size() - s.size());
    }
    return "";
}

Medium rowMedium(const LensTable& table, const LensTableRow& r, std::vector<LensWarning>& warnings) {
    if (!r.glass.empty()) {
        const Medium glass = catalogMedium(table, r, warnings);
        // A table's N that disagrees with the glass named beside it is a typo in one of them. A .zmx
        // or .seq file's figures are whatever its writer left there (often a placeholder): its name rules.
        constexpr double kIndexTolerance = 2e-3;
        if (table.format == "table" && r.index > 1 && std::fabs(r.index - glass.nd) > kIndexTolerance) {
            std::ostringstream msg;
            msg.precision(6);
            msg << "N " << r.index << " contradicts " << glass.name << " (" << glass.catalog << "), whose nd is "
                << glass.nd << ": correct the index or the glass name";
            throw LensTableError(table.name, r.line, msg.str());
        }
        return glass;
    }
    if (r.abbe > 0) {
        if (!(r.index > 1))
            throw LensTableError(table.name, r.line, "an Abbe number needs a refractive index above 1 beside it");
        return modelGlass(r.index, r.abbe);
    }
    return r.index == 0 || r.index == 1 ? air() : constantIndex(r.index);
}

std::optional<std::string> wavelengthsBeyondData(const LensTable& table, const LensTableRow& row, const Medium& medium) {
    const bool model = row.glass.empty() && row.abbe > 0;
    const double first = model ? kVisibleFirstNm : medium.minNm, last = model ? kVisibleLastNm : medium.maxNm;
    if (!(last > first)) return std::nullopt;
    std::vector<double> nm = table.wavelengths;
    nm.push_back(table.primaryWavelength);
    std::sort(nm.begin(), nm.end());
    nm.erase(std::unique(nm.begin(), nm.end()), nm.end());
    std::string outside;
    for (double w : nm)
        if (w < first || w > last)
            outside += (outside.empty() ? "" : ", ") + formatNumber(w) + " nm (n " + formatNumber(refractiveIndex(medium, w), 6) + ")";
    if (outside.empty()) return std::nullopt;
    const std::string what = model ? "model glass " + formatNumber(row.index, 6) + "/" + formatNumber(row.abbe, 4) +
                                         ", fitted to the visible,"
                                   : medium.name + (medium.catalog.empty() ? "" : " (" + medium.catalog + ")") + "'s data";
    return what + " cover" + (model ? "s " : " ") + formatNumber(first) + "-" + formatNumber(last) +
           " nm: its index is extrapolated to " + outside;
}

}  // namespace lenslab
