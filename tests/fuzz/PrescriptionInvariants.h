#pragma once
// What every accepted prescription holds, whichever file it was read from: the fuzz targets of
// the .zmx and .seq readers check these and then what their own format adds.
#include <cmath>

#include "FuzzCheck.h"
#include "prescription/LensTable.h"

namespace lenslab::fuzz {

inline void checkRowGeometry(const LensTableRow& r) {
    check(std::isfinite(r.radius) && std::isfinite(r.gap) && std::isfinite(r.conic), "finite geometry");
    for (double a : r.aspheric) check(std::isfinite(a), "finite aspheric terms");
}

// A stated clear aperture is positive and finite; an automatic one (the file leaves it to the
// program) is 0 until the lens is built.
inline void checkRowDiameter(const LensTableRow& r) {
    if (r.automaticDiameter) check(r.diameter == 0 && !r.clearShape, "an automatic aperture states no size");
    else check(r.diameter > 0 && std::isfinite(r.diameter), "a stated diameter is positive and finite");
}

inline void checkRowMedium(const LensTableRow& r) {
    check(r.abbe >= 0 && std::isfinite(r.abbe), "finite Abbe number >= 0");
    check(r.line >= 1, "rows name their line");
}

// One stop among the rows, at most kMaxLensSurfaces of them, positive finite wavelengths.
inline void checkTableWhole(const LensTable& t, int stops) {
    check(!t.rows.empty() && t.rows.size() <= std::size_t(kMaxLensSurfaces), "1..kMaxLensSurfaces rows");
    check(stops == 1, "exactly one stop");
    for (double w : t.wavelengths) check(w > 0 && std::isfinite(w), "positive finite wavelengths");
    check(t.primaryWavelength > 0 && std::isfinite(t.primaryWavelength), "a positive primary wavelength");
}

}  // namespace lenslab::fuzz
