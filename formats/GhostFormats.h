#pragma once
// The ghost analysis (optics/analysis/GhostAnalysis.h) as the table `lenslab analyze --ghosts`
// prints and as the JSON `--ghosts --json`, GET /api/lenses/{id}/ghosts and the report use.
// Surfaces are numbered from 1, as the lens's surface table numbers them; NaN becomes null.
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/GhostAnalysis.h"

namespace lenslab {

std::string ghostAnalysisText(const GhostAnalysis& ghosts, const LensAnalysis& lens);
nlohmann::json ghostAnalysisJson(const GhostAnalysis& ghosts);

}  // namespace lenslab
