#include "AnalysisViews.h"

#include "AnalysisPlots.h"
#include "AnalysisTables.h"

namespace lenslab {

nlohmann::json analysisViewsJson(const LensDesignAnalysis& analysis, bool curves) {
    nlohmann::json plots = nlohmann::json::array();
    for (const NamedSvg& plot : designAnalysisPlots(analysis, curves))
        plots.push_back({{"name", plot.name}, {"caption", plot.caption}, {"svg", plot.svg}});
    return {{"settings_html", analysisSettingsHtml(analysis)}, {"tables_html", analysisTablesHtml(analysis, curves)}, {"plots", plots}};
}

}  // namespace lenslab
