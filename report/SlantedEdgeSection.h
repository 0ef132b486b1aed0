#pragma once
// The report's check of the picture against the numbers: for two lenses, edges of the slanted-edge
// chart on the axis and at about 0.7 of the film's field, each crop's e-SFR plotted against the
// analysis's MTF times the pixel's (SlantedEdgeComparison.h). Each comparison is an item of the
// cache, keyed by the scene, the lens table and the settings.
#include <string>
#include <vector>

#include "BuildReport.h"
#include "ItemRunner.h"
#include "ReportContent.h"
#include "SceneFiles.h"
#include "SlantedEdgeComparison.h"
#include "SvgPlot.h"

namespace lenslab {

// "tangential" | "sagittal"
const char* edgeDirectionName(MtfDirection d);

// One comparison's plot: the render's e-SFR as markers over the analysis times the pixel, with the
// two factors and half the pixel Nyquist dashed; lp/mm from 0 to the pixel Nyquist.
Plot slantedEdgePlot(const EdgeComparison& e, const std::string& lensId, const std::string& id);

// Items this section makes for the report's lenses (for the progress count).
int slantedEdgeItemCount(const std::vector<std::string>& lensIds);

// The comparisons for those of the section's lenses that the report has.
SlantedEdges buildSlantedEdges(ItemRunner& runner, const SceneSource& chart, const std::vector<LensEntry>& lenses,
                               const ReportOptions& options);

// <section id="render-against-analysis">; nothing when the report has neither lens.
std::string slantedEdgeSectionHtml(const SlantedEdges& edges);

}  // namespace lenslab
