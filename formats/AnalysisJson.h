#pragma once
// The lens designer's analysis as JSON: the shape `lenslab analyze --json` prints, `-o` writes as
// analysis.json and GET /api/lenses/{id}/analysis serves. Millimetres, nm, degrees, lp/mm; lens
// space (image points relative to the d line's chief ray on the image plane). NaN becomes null.
#include <nlohmann/json.hpp>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

// Spot points beyond this many per spot are subsampled evenly (the statistics use them all).
constexpr std::size_t kMaxJsonSpotPoints = 500;

nlohmann::json designAnalysisJson(const LensDesignAnalysis& analysis);

}  // namespace lenslab
