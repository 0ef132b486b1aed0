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

// Where the lenses two tables build differ beyond `tolerance` (mm, and for directions): the surfaces
// (count, z, radius, conic, semi-diameter, stop, mirror, index) and a fan of rays from the object
// side traced to the image space (blocked or not, where and in which direction they leave). For
// tables that state one lens in different rows: a Code V decentre written as Zemax coordinate breaks.
std::optional<std::string> builtLensDifference(const LensTable& a, const LensTable& b, double tolerance);

}  // namespace lenslab
