#pragma once
// What a page shows of an analysis, as the report shows it: the settings and the numbers as HTML
// (AnalysisTables.h) and the plots as SVG (AnalysisPlots.h). The API answers it to the web page,
// which inlines it instead of plotting again.
#include <nlohmann/json.hpp>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

// {"settings_html", "tables_html", "plots": [{"name", "caption", "svg"}, ...]}, in designAnalysisPlots'
// order. `curves`: as for designAnalysisPlots.
nlohmann::json analysisViewsJson(const LensDesignAnalysis& analysis, bool curves = true);

}  // namespace lenslab
