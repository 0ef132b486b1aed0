#pragma once
// The lens designer's analysis as JSON: the shape `lenslab analyze --json` prints, `-o` writes as
// analysis.json and GET /api/lenses/{id}/analysis serves. Millimetres, nm, degrees, lp/mm; lens
// space (spot and fan points relative to each field's reference point on the image plane). NaN becomes
// null. Every number's definition (image plane, reference, pupil sampling) travels with it.
#include <nlohmann/json.hpp>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

// Spot points beyond this many per spot are subsampled evenly (the statistics use them all).
constexpr std::size_t kMaxJsonSpotPoints = 500;

nlohmann::json designAnalysisJson(const LensDesignAnalysis& analysis);

}  // namespace lenslab
