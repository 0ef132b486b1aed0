#pragma once
// The ghost analysis as a plot (SVG): every ghost's blur on the film against its peak intensity
// beside the direct image, both logarithmic, focused ghosts marked apart; the dangerous ones sit
// at the top left.
#include <string>

#include "analysis/GhostAnalysis.h"

namespace lenslab {

std::string ghostPlotSvg(const GhostAnalysis& ghosts, const std::string& id);

}  // namespace lenslab
