#pragma once
// What the lens table writer (.dat) does not write: the decentres, tilts, surface forms,
// shaped apertures, automatic apertures and glass substitutions a .zmx or .seq can bring (issue 29).
// A writer refuses a lens that has any, rather than write a different lens.
#include "prescription/LensTable.h"

namespace lenslab {

// Throws LensTableError naming the row (0: the table as a whole) and the first such feature.
void refuseUnwrittenFeatures(const LensTable& table, const std::string& format);

}  // namespace lenslab
