#pragma once
// A LensTable as a Code V sequence file (.seq: RDM radii, millimetres) that parseCodeV reads back to
// the same rows (docs/prescriptions.md, "Writing prescriptions"). The rows must be gap-after (S's
// thickness is the gap to the next surface).
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

// The table as its .seq states it, so as parseCodeV reads it back; the same lens. A .seq has no
// file-wide catalog list: the table's (Zemax's GCAT) becomes each glass row's own catalog
// (N-BK7_SCHOTT). A catalog glass is its name (the nd and Vd beside it are not stated), an air row
// of N 1 is air, a mirror's row holds the medium the light arrived in (REFL reflects back into it),
// and a coordinate break of no thickness is nothing where it moves nothing, and else, before a
// surface without a decentre of its own, that surface's basic decentre.
LensTable asCodeVStatesIt(LensTable table);

// The .seq text of asCodeVStatesIt(table), ending with GO. Throws LensTableError naming the row's
// line (0: the file as a whole) for what a .seq, as lenslab reads it, cannot hold rather than write
// another lens: a medium of plain index (no Abbe number), surface kinds other than the even
// asphere, an r^2 aspheric term, coatings, glass substitutions, other coordinate breaks, a tilt
// before its decentre (Zemax's order flag 1), text that cannot stand quoted on one line.
std::string writeCodeVText(const LensTable& table);

}  // namespace lenslab
