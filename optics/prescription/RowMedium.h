#pragma once
// The medium behind a prescription row: the file's own substitutions first, then the catalogs (a
// moulded variant falling back to its base glass with a warning), a model glass, or a plain index.
#include <optional>
#include <string>
#include <vector>

#include "prescription/LensTable.h"
#include "prescription/Medium.h"

namespace lenslab {

// Throws LensTableError naming the row's line for an unknown glass (with the catalogs searched and
// the nearest names), a substitution naming an unknown glass, a catalog glass whose nd contradicts
// a lens table's N. Appends to `warnings` when a moulded variant is taken as its base glass.
Medium rowMedium(const LensTable& table, const LensTableRow& row, std::vector<LensWarning>& warnings);

// Why the index of the medium behind `row` is an extrapolation at a wavelength the prescription
// lists (or its primary), or nullopt: a catalog glass or a measured table whose data do not reach
// it, or a model glass (its nd and Vd describe the visible) outside 360-830 nm. The lens still reads;
// the designer should know. Plain indices have no data to leave.
std::optional<std::string> wavelengthsBeyondData(const LensTable& table, const LensTableRow& row, const Medium& medium);

// A moulded variant's base glass name ("L-TIM28_MOLD" -> "L-TIM28"); empty when the name is not one.
std::string mouldedBaseName(const std::string& name);

}  // namespace lenslab
