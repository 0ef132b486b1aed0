#pragma once
// Code V sequence files (.seq) as a LensTable: the other prescription format lens designers and
// patents' transcriptions use (docs/prescriptions.md, "Code V files").
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

// Parses a Code V sequence file (UTF-8, or UTF-16 with a byte order mark) into a gap-after table in
// millimetres. `name` is used in messages. Throws LensTableError (file, line, problem) naming the
// command for every command lenslab does not read and for values it cannot model.
LensTable parseCodeV(const std::string& bytes, const std::string& name);

// True when the text (already UTF-8) is a Code V file by its content: its first command is one a
// Code V file starts with (RDM, LEN, TIT/TITLE, DIM, SO, WL, EPD, ...). A lens table starts with a
// comment or a number, a Zemax file with VERS, MODE, NAME, NOTE, UNIT or SURF.
bool looksLikeCodeV(const std::string& text);

}  // namespace lenslab
