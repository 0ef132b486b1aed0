#pragma once
// The makers' catalog glasses (optics/data/glass-catalog.tsv, converted from the public-domain
// refractiveindex.info database), found by name as lens designers write them. docs/glass.md
// gives the catalogs, the matching rules and the formulas.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "prescription/Medium.h"

namespace lenslab {

struct GlassLookup {
    std::optional<Medium> glass;           // empty: no glass of that name
    std::vector<std::string> searched;     // the makers, in the order they were searched
    std::vector<std::string> suggestions;  // when not found: the nearest names, nearest first
};

// The longest name a glass is looked up by (the catalogs' longest is 13 characters): a longer one
// is unknown at once, without the search for the nearest names (an edit distance against every
// glass, which a name of a megabyte would make cost seconds).
constexpr std::size_t kMaxGlassNameLength = 32;

// A glass name as findGlass compares it: upper case, without spaces, underscores and hyphens.
std::string glassNameKey(std::string_view name);

// Finds a catalog glass by name: case, spaces, underscores and hyphens do not matter, and a name
// without its maker prefix ("BK7", "LAH64", "LAK02") finds the prefixed glass. preferredCatalogs
// (a .zmx GCAT line: "SCHOTT", "OHARA", "SUMITA_AUG2011", ...) are searched first, then the
// catalogs loaded at run time before the bundled makers, then the makers, then the catalogs loaded
// after them (addGlassCatalog).
GlassLookup findGlass(const std::string& name, const std::vector<std::string>& preferredCatalogs = {});
std::vector<std::string> glassCatalogNames();  // the bundled makers, in the default search order

// Where a catalog loaded at run time is searched: before the bundled makers (the command line's
// --glass-catalog: the user's own choice of glass data), or after them and after every catalog
// loaded before it (the service's uploads: a catalog anyone may upload adds glasses but never
// changes what a name found elsewhere means, so no upload changes a lens read before it; a .zmx
// GCAT line does not move it forward).
enum class CatalogPrecedence { BeforeBundled, AfterBundled };

// Adds a catalog loaded at run time (an AGF file's glasses, GlassCatalogFile.h); a catalog of the
// same name replaces the one loaded before. Thread-safe, as are the lookups beside it.
void addGlassCatalog(const std::string& name, std::vector<Medium> glasses,
                     CatalogPrecedence precedence = CatalogPrecedence::BeforeBundled);
// Removes a loaded catalog by name (compared as glass names are); false when none has that name.
bool removeGlassCatalog(const std::string& name);
// Whether a loaded catalog or a bundled maker has that name (compared as glass names are).
bool isGlassCatalogName(const std::string& name);
std::vector<std::string> loadedGlassCatalogNames();  // in load order
// The glasses of the catalogs loaded with that precedence, in search order.
std::vector<Medium> loadedGlasses(CatalogPrecedence precedence);
// For each loaded catalog (by name), the names of its glasses that a lookup by that very name finds
// in a catalog searched before it (without GCAT lines): the glasses it holds but no lens gets from it.
std::map<std::string, std::vector<std::string>> shadowedGlassNames();
void clearLoadedGlassCatalogs();
std::size_t glassCount();
const std::vector<Medium>& catalogGlasses();   // every glass, maker by maker

}  // namespace lenslab
