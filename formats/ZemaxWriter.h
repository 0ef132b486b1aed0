#pragma once
// A LensTable as a sequential Zemax .zmx file (UTF-8, millimetres, STANDARD and EVENASPH surfaces):
// parseZemax reads it back to the same rows. The rows must be gap-after (a .zmx DISZ is the
// thickness to the next surface).
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

std::string writeZemaxText(const LensTable& table);

}  // namespace lenslab
