#pragma once
// A lens analysis as JSON: the shape `lenslab lens --json` prints and the API serves.
#include <nlohmann/json.hpp>

#include "settings/LensAnalysis.h"

namespace lenslab {

nlohmann::json lensAnalysisJson(const LensAnalysis& analysis);

// A lens's warnings: [{"line": N, "message": "..."}] (line 0: the file as a whole).
nlohmann::json warningsJson(const std::vector<LensWarning>& warnings);

}  // namespace lenslab
