#pragma once
// A LensTable as a sequential Zemax .zmx file (UTF-8, millimetres, STANDARD and EVENASPH surfaces):
// parseZemax reads it back to the same rows. The rows must be gap-after (a .zmx DISZ is the
// thickness to the next surface).
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

std::string writeZemaxText(const LensTable& table);

// The table as its .zmx states it: each row's own catalog (Code V's N-BK7_SCHOTT) joins the file's
// catalogs (GCAT), in the order the rows name them. writeZemaxText refuses a lens where that order
// would find another glass for some row.
LensTable withRowCatalogsInTheFile(LensTable table);

}  // namespace lenslab
