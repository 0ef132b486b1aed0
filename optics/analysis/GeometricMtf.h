#pragma once
// The geometric MTF of a spot: each ray carries the light of its share of the pupil, so the line
// spread along a direction is the spot's points projected on it, and its Fourier transform at nu is
// the weighted mean of exp(2 pi i nu u_k) over the points' coordinates u_k. Several wavelengths' spots (each relative to
// the same reference point) combine with their weights, lateral colour included.
#include <vector>

#include "analysis/SpotDiagram.h"

namespace lenslab {

// Sagittal: frequency along x (lines along the field's radius); tangential: along y.
enum class MtfDirection { Sagittal, Tangential };

// |sum_k w_k exp(2 pi i nu u_k)| / sum_k w_k at each frequency (lp/mm); ray k of spot j weighs
// weights[j] times its pupil share. 0 everywhere when no ray passed.
std::vector<double> geometricMtf(const std::vector<SpotDiagram>& spots, const std::vector<double>& weights,
                                 MtfDirection direction, const std::vector<double>& frequencies);

}  // namespace lenslab
