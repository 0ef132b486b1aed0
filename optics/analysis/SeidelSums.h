#pragma once
// The third-order (Seidel) aberrations of a centred lens, surface by surface, from its paraxial
// marginal and chief rays (Welford, Aberrations of Optical Systems, ch. 8): spherical aberration
// S_I, coma S_II, astigmatism S_III, Petzval S_IV, distortion S_V, and the primary axial and lateral
// colour C_I, C_II, in mm (the wavefront coefficients: W040 = S_I / 8, W131 = S_II / 2,
// W222 = S_III / 2, W220 = (S_III + S_IV) / 4, W311 = S_V / 2). A conic or an r^4 aspheric term
// adds its own share (the stop-shift terms of a thin plate at the surface).
#include <optional>
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct SeidelTerms {
    double spherical = 0, coma = 0, astigmatism = 0, petzval = 0, distortion = 0;
    double axialColour = 0, lateralColour = 0;  // F less C
};

struct SeidelSums {
    double fieldDegrees = 0;        // the chief ray's angle in object space (slope tan of it)
    double marginalHeight = 0;      // the marginal ray's height at the stop: the stop's radius, mm
    double lagrangeInvariant = 0;   // H = n (ubar y - u ybar), mm
    std::vector<SeidelTerms> surfaces;  // per surface, in order
    SeidelTerms total;
};

// The sums of the lens at its own stop opening, for the object at objectZ (lens z; infinity: a
// distant object) and a chief ray at fieldDegrees. The marginal ray enters from the axial object
// point and fills the stop; the chief ray crosses the stop's centre. Nullopt for a lens the
// paraxial theory here does not cover: decentred or tilted surfaces, mirrors, forms beyond the even
// asphere, or a stop no paraxial ray reaches.
std::optional<SeidelSums> seidelSums(const LensSystem& lens, double fieldDegrees, double objectZ);

}  // namespace lenslab
