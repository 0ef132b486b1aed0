#pragma once
// Glass catalogs beyond the bundled one, for every subcommand: --glass-catalog FILE.agf (repeatable)
// and the folder named by LENSLAB_GLASS_CATALOGS (every .agf in it), loaded before the command runs.
#include <string>
#include <vector>

namespace lenslab {

// Loads the catalogs (the folder's first, then the flags' in order; a later catalog of the same
// name replaces an earlier one) and returns the arguments without the flags. Throws UsageError for
// a flag without a file, LensTableError for a catalog that does not read.
std::vector<std::string> loadGlassCatalogs(const std::vector<std::string>& args);

}  // namespace lenslab
