#include "design/GlassSnap.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "prescription/GlassCatalog.h"

namespace lenslab {

namespace {

bool sameName(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

}  // namespace

std::optional<Medium> nearestCatalogGlass(double nd, double vd, const std::vector<std::string>& catalogs) {
    std::optional<Medium> best;
    double nearest = std::numeric_limits<double>::infinity();
    const auto consider = [&](const Medium& m) {
        if (!(m.vd > 0)) return;  // a crystal without dispersion data is no stand-in for a glass
        if (!catalogs.empty() &&
            std::none_of(catalogs.begin(), catalogs.end(), [&](const std::string& c) { return sameName(c, m.catalog); }))
            return;
        const double d = std::hypot(100 * (m.nd - nd), m.vd - vd);
        if (d < nearest) nearest = d, best = m;
    };
    for (const Medium& m : loadedGlasses(CatalogPrecedence::BeforeBundled)) consider(m);
    for (const Medium& m : catalogGlasses()) consider(m);
    for (const Medium& m : loadedGlasses(CatalogPrecedence::AfterBundled)) consider(m);
    return best;
}

std::vector<GlassChoice> snapToCatalogGlasses(LensTable& table, const std::vector<int>& rows, const std::vector<std::string>& catalogs) {
    std::vector<GlassChoice> out;
    std::vector<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    for (int row : sorted) {
        if (row < 0 || row >= int(table.rows.size())) continue;
        LensTableRow& r = table.rows[row];
        if (!r.glass.empty() || !(r.abbe > 0) || !(r.index > 1)) continue;
        const std::optional<Medium> glass = nearestCatalogGlass(r.index, r.abbe, catalogs);
        if (!glass) continue;
        out.push_back({row, r.index, r.abbe, *glass, std::hypot(100 * (glass->nd - r.index), glass->vd - r.abbe)});
        r.glass = glass->name;
        r.glassCatalog = glass->catalog;
        r.index = glass->nd;
        r.abbe = 0;
    }
    return out;
}

}  // namespace lenslab
