#pragma once
// A prescription's rows as JSON, for the live editor: every field of the LensTable that the writers
// write, so that a lens edited and written out keeps what the editor does not show (docs/api.md,
// "Editing a prescription"):
//   {"name", "layout": "gap-after", "comments", "catalogs", "wavelengths_nm", "wavelength_weights",
//    "primary_wavelength_nm", "fields", "object_distance" (mm, null: at infinity),
//    "entrance_pupil_diameter", "f_number", "object_numerical_aperture" (null: none), "image_frame",
//    "rows": [{radius, gap, index, diameter, stop, glass, glass_catalog, abbe, conic, aspheric[8],
//              mirror, obscuration_diameter, coating, name, kind, form_terms, normalisation_radius,
//              clear_aperture, obscuration, frame, coordinate_break, automatic_diameter}]}
// (apertures, frames, forms and fields as PrescriptionPartsJson.h writes them; coating: the text of
// prescription/Coating.h, "" for the default). Rows are always gap-after (gap: the thickness to the
// next surface, as designers and .zmx files write it); the last gap is the design's image distance,
// which no analysis uses. Glass substitutions (a .smx beside the file) are not carried: no writer
// writes them.
#include <nlohmann/json.hpp>

#include "prescription/LensTable.h"

namespace lenslab {

// The same lens with gap-after rows (a gap-before table's gaps move up one row).
LensTable withGapAfterRows(LensTable table);

nlohmann::json prescriptionJson(const LensTable& table);

// Reads rows from JSON into a gap-after table called `name`; row i gets line i + 1, so the
// geometry's errors (LensTableError) name the row. Throws LensTableError(name, row, problem) for
// a mistyped field, a name it does not know, a non-finite number, a non-positive diameter (0 for a
// coordinate break and an automatic aperture; a shaped aperture's reach), an index below 1, more
// than kMaxLensSurfaces rows. A field left out takes the LensTable's default. Everything else (the
// stop, the glass names, the sag) is buildLensSystem's to check.
LensTable prescriptionFromJson(const nlohmann::json& body, const std::string& name);

}  // namespace lenslab
