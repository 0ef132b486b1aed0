#include "prescription/GlassCatalog.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <unordered_set>
#include <utility>

#include "prescription/GlassCatalogText.h"

namespace lenslab {
namespace {

// The makers in the default search order, each with its name prefixes, its current line first.
// Schott leads because the bare old names designers write (BK7, SF5, SK16) are Schott's; Hikari's
// J-BK7 and Sumita's K-BK7 are copies of it under the makers' prefixes. The others follow in a
// fixed order, so a lookup never depends on anything but its arguments.
struct Maker {
    std::string_view name;
    std::array<std::string_view, 4> prefixes;
};
constexpr std::array<Maker, 7> kMakers{{
    {"SCHOTT", {"N", "P"}},             // N: lead- and arsenic-free; P: precision moulding
    {"OHARA", {"S", "L"}},              // S: the eco line; L: low Tg, moulding
    {"HOYA", {"E", "M", "MC", "MP"}},   // E: eco; M, MC, MP: moulding
    {"CDGM", {"H", "D"}},               // H: eco; D: moulding
    {"HIKARI", {"J", "E", "Q", "P"}},   // J: today's eco line; E: the earlier one; Q, P: moulding
    {"SUMITA", {"K"}},
    {"MISC", {}},                       // Zemax's MISC: fused silica and crystals, measured, no maker
}};
constexpr std::size_t kSuggestions = 5;

// "S-LAH64": prefix "S", rest "LAH64". Prefixes are one or two letters before the first hyphen.
std::pair<std::string_view, std::string_view> splitPrefix(std::string_view name) {
    const std::size_t hyphen = name.find('-');
    const std::string_view prefix = name.substr(0, hyphen);
    const bool letters = std::all_of(prefix.begin(), prefix.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
    if (hyphen == std::string_view::npos || hyphen < 1 || hyphen > 2 || !letters) return {{}, name};
    return {prefix, name.substr(hyphen + 1)};
}

struct GlassNames {
    std::string key;         // the whole name
    std::string base;        // the name without its maker prefix; "" when it has none
    std::size_t maker = 0;   // index in kMakers
    std::size_t prefixRank = 0;  // the prefix's place in the maker's list (unlisted prefixes last)
};

struct Catalog {
    std::vector<Medium> glasses;
    std::vector<GlassNames> names;  // parallel to glasses
};

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

[[noreturn]] void badLine(std::size_t line, const std::string& why) {
    throw std::runtime_error("glass-catalog.tsv line " + std::to_string(line) + ": " + why);
}

double number(std::string_view text, std::size_t line) {
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) badLine(line, "bad number '" + std::string(text) + "'");
    return value;
}

DispersionFormula formulaNamed(std::string_view name, std::size_t line) {
    if (name == "Sellmeier") return DispersionFormula::Sellmeier;
    if (name == "SchottPolynomial") return DispersionFormula::SchottPolynomial;
    badLine(line, "unknown formula '" + std::string(name) + "'");
}

// A glass's names as compared; `prefixes` are its maker's, in preference order (none for a loaded catalog).
GlassNames namesIn(const Medium& glass, const std::array<std::string_view, 4>& prefixes) {
    GlassNames names;
    names.key = glassNameKey(glass.name);
    const auto [prefix, rest] = splitPrefix(glass.name);
    if (!prefix.empty()) names.base = glassNameKey(rest);
    names.prefixRank = static_cast<std::size_t>(std::find(prefixes.begin(), prefixes.end(), prefix) - prefixes.begin());
    return names;
}

GlassNames namesOf(const Medium& glass, std::size_t line) {
    const auto maker = std::find_if(kMakers.begin(), kMakers.end(), [&](const Maker& m) { return m.name == glass.catalog; });
    if (maker == kMakers.end()) badLine(line, "unknown maker '" + glass.catalog + "'");
    GlassNames names = namesIn(glass, maker->prefixes);
    names.maker = static_cast<std::size_t>(maker - kMakers.begin());
    return names;
}

// The data file: comment lines start with '#'; each other line is one glass, tab-separated:
// maker, name, formula, min nm, max nm, nd, Vd, coefficients (space-separated).
Catalog parseCatalog(std::string_view text) {
    Catalog catalog;
    const std::vector<std::string_view> lines = split(text, '\n');
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::size_t line = i + 1;
        if (lines[i].empty() || lines[i][0] == '#') continue;
        const std::vector<std::string_view> f = split(lines[i], '\t');
        if (f.size() != 8) badLine(line, "expected 8 fields, found " + std::to_string(f.size()));
        Medium glass;
        glass.catalog = f[0];
        glass.name = f[1];
        glass.formula = formulaNamed(f[2], line);
        glass.minNm = number(f[3], line);
        glass.maxNm = number(f[4], line);
        glass.nd = number(f[5], line);
        glass.vd = number(f[6], line);
        const std::vector<std::string_view> coefficients = split(f[7], ' ');
        if (coefficients.size() > glass.coefficients.size()) badLine(line, "too many coefficients");
        for (std::size_t c = 0; c < coefficients.size(); ++c) glass.coefficients[c] = number(coefficients[c], line);
        catalog.names.push_back(namesOf(glass, line));
        catalog.glasses.push_back(std::move(glass));
    }
    return catalog;
}

const Catalog& catalog() {
    static const Catalog parsed = parseCatalog(kGlassCatalogText);  // once, on first use; thread-safe
    return parsed;
}

// Catalogs loaded at run time (AGF files), in load order.
struct LoadedCatalog {
    std::string name;
    Catalog glasses;
    CatalogPrecedence precedence = CatalogPrecedence::BeforeBundled;
};
struct LoadedCatalogs {
    std::shared_mutex mutex;
    std::vector<LoadedCatalog> catalogs;
};
LoadedCatalogs& loaded() {
    static LoadedCatalogs l;
    return l;
}

std::vector<LoadedCatalog>::iterator loadedNamed(std::vector<LoadedCatalog>& catalogs, const std::string& name) {
    const std::string key = glassNameKey(name);
    return std::find_if(catalogs.begin(), catalogs.end(), [&](const LoadedCatalog& l) { return glassNameKey(l.name) == key; });
}

// Where one glass comes from in a search: a loaded catalog or a bundled maker, and its glasses.
struct Source {
    std::string name;
    const Catalog* glasses = nullptr;
    bool bundled = false;
    std::size_t maker = 0;  // bundled: index in kMakers
    bool preferable = true;  // a GCAT line may move it forward
};

// Every source in search order: preferred catalogs first (a Zemax catalog name names its maker by
// its start: "SUMITA_AUG2011"; a loaded catalog by its whole name), then the loaded catalogs, then
// the makers, then the catalogs loaded after them (never moved forward). Names of no known catalog
// are passed over.
std::vector<Source> searchOrder(const std::vector<std::string>& preferredCatalogs, const std::vector<LoadedCatalog>& user) {
    std::vector<Source> all;
    const auto addLoaded = [&](CatalogPrecedence precedence) {
        for (const LoadedCatalog& c : user)
            if (c.precedence == precedence)
                all.push_back({c.name, &c.glasses, false, 0, precedence == CatalogPrecedence::BeforeBundled});
    };
    addLoaded(CatalogPrecedence::BeforeBundled);
    const Catalog& bundled = catalog();
    for (std::size_t m = 0; m < kMakers.size(); ++m) all.push_back({std::string(kMakers[m].name), &bundled, true, m, true});
    addLoaded(CatalogPrecedence::AfterBundled);
    std::vector<Source> order;
    std::vector<bool> taken(all.size(), false);
    for (const std::string& wanted : preferredCatalogs) {
        const std::string key = glassNameKey(wanted);
        for (std::size_t i = 0; i < all.size(); ++i) {
            const std::string name = glassNameKey(all[i].name);
            const bool named = all[i].bundled ? key.compare(0, name.size(), name) == 0 : key == name;
            if (named && all[i].preferable && !taken[i]) {
                taken[i] = true;
                order.push_back(all[i]);
            }
        }
    }
    for (std::size_t i = 0; i < all.size(); ++i)
        if (!taken[i]) order.push_back(all[i]);
    return order;
}

// The glasses of one source: a loaded catalog's all, a maker's those of the bundled file it made.
template <class Visit>
void forEachGlass(const Source& source, Visit visit) {
    const Catalog& c = *source.glasses;
    for (std::size_t i = 0; i < c.glasses.size(); ++i)
        if (!source.bundled || c.names[i].maker == source.maker) visit(c.glasses[i], c.names[i]);
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = diagonal + (a[i - 1] != b[j - 1] ? 1 : 0);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

// The names nearest to a key (with or without their prefix), ties in search order, then by name.
std::vector<std::string> nearestNames(const std::string& key, const std::vector<Source>& order) {
    std::vector<std::tuple<std::size_t, std::size_t, std::string_view>> ranked;
    for (std::size_t position = 0; position < order.size(); ++position)
        forEachGlass(order[position], [&](const Medium& glass, const GlassNames& n) {
            std::size_t distance = editDistance(key, n.key);
            if (!n.base.empty()) distance = std::min(distance, editDistance(key, n.base));
            ranked.emplace_back(distance, position, glass.name);
        });
    std::sort(ranked.begin(), ranked.end());
    std::vector<std::string> names;
    for (const auto& entry : ranked) {
        const std::string name(std::get<2>(entry));
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        if (names.size() == kSuggestions) break;
    }
    return names;
}

}  // namespace

std::string glassNameKey(std::string_view name) {
    std::string key;
    for (const char c : name)
        if (!std::isspace(static_cast<unsigned char>(c)) && c != '_' && c != '-')
            key += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return key;
}

// The catalogs are searched one after the other, preferred ones first, as a .zmx GCAT line asks.
// Within a maker a glass whose whole name matches comes before one that matches without its
// prefix, so a name that exists as written is taken as written: SF5 is Schott's lead SF5, not
// N-SF5, because the design was made with that glass's dispersion. Old names therefore map to
// new ones only where the old glass is not in the data (BK7 -> N-BK7, SK16 -> N-SK16), never
// new to old (N-SF5 never finds SF5). Then the maker's prefix order (Hikari J- before E-) decides.
GlassLookup findGlass(const std::string& name, const std::vector<std::string>& preferredCatalogs) {
    LoadedCatalogs& user = loaded();
    std::shared_lock lock(user.mutex);
    const std::vector<Source> order = searchOrder(preferredCatalogs, user.catalogs);
    GlassLookup lookup;
    for (const Source& source : order) lookup.searched.push_back(source.name);

    if (name.size() > kMaxGlassNameLength) return lookup;
    const std::string key = glassNameKey(name);
    const Medium* best = nullptr;
    std::tuple<std::size_t, int, std::size_t, std::string_view> bestRank;
    for (std::size_t position = 0; position < order.size(); ++position)
        forEachGlass(order[position], [&](const Medium& glass, const GlassNames& n) {
            const int tier = key == n.key ? 0 : (!n.base.empty() && key == n.base) ? 1 : -1;
            if (tier < 0) return;
            const auto rank = std::make_tuple(position, tier, n.prefixRank, std::string_view(glass.name));
            if (!best || rank < bestRank) {
                best = &glass;
                bestRank = rank;
            }
        });
    if (best) lookup.glass = *best;
    else lookup.suggestions = nearestNames(key, order);
    return lookup;
}

void addGlassCatalog(const std::string& name, std::vector<Medium> glasses, CatalogPrecedence precedence) {
    LoadedCatalog c;
    c.name = name;
    c.precedence = precedence;
    for (Medium& glass : glasses) {
        glass.catalog = name;
        c.glasses.names.push_back(namesIn(glass, {}));
        c.glasses.glasses.push_back(std::move(glass));
    }
    LoadedCatalogs& user = loaded();
    std::unique_lock lock(user.mutex);
    const auto same = loadedNamed(user.catalogs, name);
    if (same != user.catalogs.end()) *same = std::move(c);
    else user.catalogs.push_back(std::move(c));
}

bool removeGlassCatalog(const std::string& name) {
    LoadedCatalogs& user = loaded();
    std::unique_lock lock(user.mutex);
    const auto same = loadedNamed(user.catalogs, name);
    if (same == user.catalogs.end()) return false;
    user.catalogs.erase(same);
    return true;
}

bool isGlassCatalogName(const std::string& name) {
    const std::string key = glassNameKey(name);
    if (std::any_of(kMakers.begin(), kMakers.end(), [&](const Maker& m) { return glassNameKey(m.name) == key; })) return true;
    LoadedCatalogs& user = loaded();
    std::shared_lock lock(user.mutex);
    return loadedNamed(user.catalogs, name) != user.catalogs.end();
}

std::vector<Medium> loadedGlasses(CatalogPrecedence precedence) {
    LoadedCatalogs& user = loaded();
    std::shared_lock lock(user.mutex);
    std::vector<Medium> glasses;
    for (const LoadedCatalog& c : user.catalogs)
        if (c.precedence == precedence) glasses.insert(glasses.end(), c.glasses.glasses.begin(), c.glasses.glasses.end());
    return glasses;
}

// A lookup by a glass's own name matches an earlier source's glass by its whole name or its name
// without the prefix; the earlier sources' names as a set answer that for every glass at once.
std::map<std::string, std::vector<std::string>> shadowedGlassNames() {
    LoadedCatalogs& user = loaded();
    std::shared_lock lock(user.mutex);
    std::map<std::string, std::vector<std::string>> shadowed;
    std::unordered_set<std::string> earlier;
    for (const Source& source : searchOrder({}, user.catalogs)) {
        if (!source.bundled) {
            std::vector<std::string>& names = shadowed[source.name];
            forEachGlass(source, [&](const Medium& glass, const GlassNames& n) {
                if (earlier.count(n.key)) names.push_back(glass.name);
            });
        }
        forEachGlass(source, [&](const Medium&, const GlassNames& n) {
            earlier.insert(n.key);
            if (!n.base.empty()) earlier.insert(n.base);
        });
    }
    return shadowed;
}

void clearLoadedGlassCatalogs() {
    LoadedCatalogs& user = loaded();
    std::unique_lock lock(user.mutex);
    user.catalogs.clear();
}

std::vector<std::string> loadedGlassCatalogNames() {
    LoadedCatalogs& user = loaded();
    std::shared_lock lock(user.mutex);
    std::vector<std::string> names;
    for (const LoadedCatalog& c : user.catalogs) names.push_back(c.name);
    return names;
}

std::vector<std::string> glassCatalogNames() {
    std::vector<std::string> names;
    for (const Maker& maker : kMakers) names.emplace_back(maker.name);
    return names;
}

std::size_t glassCount() { return catalog().glasses.size(); }

const std::vector<Medium>& catalogGlasses() { return catalog().glasses; }

}  // namespace lenslab
