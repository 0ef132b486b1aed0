#pragma once
// A table's glass substitutions as the .smx file beside its prescription (ray-optics' form, as
// prescription/SubstitutionFile.h reads it): how a lens whose glasses no catalog holds (an as-built
// lens's melts, a table of measured indices) is written and read back exactly.
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

// The substitutions as .smx JSON: tables of indices as InterpolatedMedium pairs (nm, n), constant
// indices as ConstantIndex, catalog glasses as [glass, catalog]. Throws LensTableError (line 0) for a
// medium given outright by a formula (it has no .smx form).
std::string writeSubstitutionText(const LensTable& table);

// The table as its prescription file states it beside the .smx: the substitutions left to that file.
LensTable withoutSubstitutions(LensTable table);

}  // namespace lenslab
