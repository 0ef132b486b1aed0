#pragma once
// A LensTable as lens-table text (.dat, the fifth column naming the glass or giving Vd), in the
// table's own layout: parseLensTable reads it back to the same rows (with that layout given).
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

// Throws LensTableError naming the row's line for what a .dat cannot hold: conics, aspheric terms,
// mirrors, obscurations, a curved stop, a glass name with spaces, a catalog glass not in the catalog.
std::string writeLensTableText(const LensTable& table);

}  // namespace lenslab
