#pragma once
// Zemax OpticStudio's sequential lens files (.zmx) as a LensTable: the prescription a lens designer
// exchanges (docs/prescriptions.md, "Zemax files").
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

// Parses a sequential Zemax .zmx prescription (UTF-8 or UTF-16 with a byte order mark) into a
// gap-after table in millimetres. `name` is used in messages. Throws LensTableError (file, line,
// problem) for what it cannot read and for what lenslab cannot model (tilts, decenters, gradient
// index, odd aspheres, other surface types, non-sequential files).
LensTable parseZemax(const std::string& bytes, const std::string& name);

// True when the bytes are a .zmx file by their content: a UTF-16 byte order mark, or a first
// non-blank line starting with one of the keywords Zemax writes first (VERS, MODE, NAME, NOTE,
// UNIT, SURF). A lens table starts with a comment or a number.
bool looksLikeZemax(const std::string& bytes);

}  // namespace lenslab
