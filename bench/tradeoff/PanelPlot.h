#pragma once
// Small multiples of line charts drawn offscreen with the diagram's GL canvas (DrawList, GlCanvas,
// TextRaster) and written as PNG: the benchmark's plot, with no plotting library.
#include <string>
#include <vector>

namespace lenslab::tradeoff {

struct Series {
    std::string label;
    std::vector<double> x, y;  // non-positive values on a log axis are left out
    bool dashed = false;
};

struct Panel {
    std::string title;
    std::string xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<Series> series;  // coloured in order from a colour-blind-safe palette
};

// Panels in a grid of `columns`, each panelWidth x panelHeight pixels. Throws on GL or PNG failure.
std::vector<unsigned char> drawPanelsPng(const std::vector<Panel>& panels, int columns, int panelWidth, int panelHeight);

}  // namespace lenslab::tradeoff
