#pragma once
// Where two lens tables differ, field by field with exact equality: how a written prescription is
// checked against the table it was written from (tests, bench/optics/prescription_round_trip).
// The source's own bookkeeping is not compared: the file name, format, whether the layout was
// detected, the rows' line numbers and the reader's warnings.
#include <optional>
#include <string>

#include "prescription/LensTable.h"

namespace lenslab {

// The first difference ("row 3 frame tilt: 1 / 2"), or nullopt where the tables are the same.
std::optional<std::string> lensTableDifference(const LensTable& a, const LensTable& b);

}  // namespace lenslab
