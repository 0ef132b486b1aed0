#pragma once
// A prescription's rows as JSON, for the live editor: {"name", "comments", "catalogs",
// "wavelengths_nm", "primary_wavelength_nm", "rows": [{radius, gap, index, diameter, stop, glass,
// abbe, conic, aspheric[8], mirror, obscuration_diameter, coating}]} (coating: the text of
// prescription/Coating.h, "" for the default). Rows are always gap-after (gap: the
// thickness to the next surface, as designers and .zmx files write it); the last gap is the
// design's image distance, which no analysis uses.
#include <nlohmann/json.hpp>

#include "prescription/LensTable.h"

namespace lenslab {

// The same lens with gap-after rows (a gap-before table's gaps move up one row).
LensTable withGapAfterRows(LensTable table);

nlohmann::json prescriptionJson(const LensTable& table);

// Reads rows from JSON into a gap-after table called `name`; row i gets line i + 1, so the
// geometry's errors (LensTableError) name the row. Throws LensTableError(name, row, problem) for
// a missing or mistyped field, a non-finite number, a non-positive diameter, an index below 1,
// more than kMaxLensSurfaces rows. Everything else (the stop, the glass names, the sag) is
// buildLensSystem's to check.
LensTable prescriptionFromJson(const nlohmann::json& body, const std::string& name);

}  // namespace lenslab
