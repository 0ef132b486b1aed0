#pragma once
// Line and scatter plots as inline SVG: axes with ticks and labels, a legend, text the browser
// renders crisply at any zoom. No plotting library; the report embeds the markup directly.
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

enum class SeriesStyle { Line, Markers, LineAndMarkers };

struct PlotSeries {
    std::string label;
    std::vector<double> x, y;  // a non-finite value breaks the line there
    SeriesStyle style = SeriesStyle::Line;
    bool dashed = false;
    double markerRadius = 3.5;  // user units; dense scatters (spot diagrams) want smaller dots
};

struct PlotAxis {
    std::string label;                  // with the unit, e.g. "film radius (mm)"
    bool logarithmic = false;
    std::optional<double> min, max;     // unset: from the data (linear axes include 0 when near)
};

struct Plot {
    std::string id;     // unique in the page (clip path and title ids derive from it)
    std::string title;  // the accessible name, also drawn above the plot
    PlotAxis x, y;
    std::vector<PlotSeries> series;  // coloured in order from a colour-blind-safe palette
    int width = 480, height = 300;   // user units; the SVG scales to its container
};

// The <svg> element for the plot.
std::string svgPlot(const Plot& plot);

}  // namespace lenslab
