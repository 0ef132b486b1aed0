#pragma once
// The makers' catalog glasses (optics/data/glass-catalog.tsv, converted from the public-domain
// refractiveindex.info database), found by name as lens designers write them. docs/glass.md
// gives the catalogs, the matching rules and the formulas.
#include <cstddef>
#include <optional>
#include <string>
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

// Finds a catalog glass by name: case, spaces, underscores and hyphens do not matter, and a name
// without its maker prefix ("BK7", "LAH64", "LAK02") finds the prefixed glass. preferredCatalogs
// (a .zmx GCAT line: "SCHOTT", "OHARA", "SUMITA_AUG2011", ...) are searched first, then the
// catalogs loaded at run time (addGlassCatalog), then the bundled makers.
GlassLookup findGlass(const std::string& name, const std::vector<std::string>& preferredCatalogs = {});
std::vector<std::string> glassCatalogNames();  // the bundled makers, in the default search order

// Adds a catalog loaded at run time (an AGF file's glasses, GlassCatalogFile.h), searched before the
// bundled makers; a catalog of the same name replaces the one loaded before. Thread-safe.
void addGlassCatalog(const std::string& name, std::vector<Medium> glasses);
std::vector<std::string> loadedGlassCatalogNames();  // in load order
void clearLoadedGlassCatalogs();
std::size_t glassCount();
const std::vector<Medium>& catalogGlasses();   // every glass, maker by maker

}  // namespace lenslab
