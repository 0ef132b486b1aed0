#include "GhostPlot.h"

#include <algorithm>

#include "prescription/NumberText.h"
#include "SvgPlot.h"

namespace lenslab {

std::string ghostPlotSvg(const GhostAnalysis& g, const std::string& id) {
    Plot p;
    p.id = id;
    p.title = "Ghosts: blur on the film against intensity (" + std::to_string(g.ghosts.size()) + " paths)";
    p.x.label = "blur diameter on the film (mm)";
    p.y.label = "peak intensity / direct image (sun-sized source)";
    p.x.logarithmic = p.y.logarithmic = true;
    PlotSeries focused, other;
    focused.label = "focused near the film (blur < " + formatNumber(kFocusedGhostDiameterMm) + " mm)";
    other.label = "defocused";
    focused.style = other.style = SeriesStyle::Markers;
    // Log axes need positive values: the tiniest blurs and intensities are held at a floor.
    constexpr double kFloor = 1e-12;
    for (const GhostImage& x : g.ghosts) {
        PlotSeries& s = x.focused ? focused : other;
        s.x.push_back(std::max(x.blurDiameter, 1e-4));
        s.y.push_back(std::max(x.relativeIntensity, kFloor));
    }
    for (PlotSeries* s : {&focused, &other})
        if (!s->x.empty()) p.series.push_back(*s);
    return svgPlot(p);
}

}  // namespace lenslab
