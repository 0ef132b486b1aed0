#pragma once
// Line and scatter plots as inline SVG: axes with ticks and labels, a legend, text the browser
// renders crisply at any zoom. No plotting library; the report embeds the markup directly.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lenslab {

enum class SeriesStyle { Line, Markers, LineAndMarkers };
enum class LineDash { Solid, Dashed, Dotted };

struct PlotSeries {
    std::string label;
    std::vector<double> x, y;  // a non-finite value breaks the line there
    SeriesStyle style = SeriesStyle::Line;
    LineDash dash = LineDash::Solid;
    double markerRadius = 3.5;  // user units; dense scatters (spot diagrams) want smaller dots
    std::string colour{};       // empty: the palette's colour for the series' place in the plot
    // Attributes written on the legend's label (data-* for readers of the markup: the exact value
    // a label rounds), as name and value.
    std::vector<std::pair<std::string, std::string>> labelAttributes{};
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
    std::vector<PlotSeries> series;  // coloured in order from a colour-blind-safe palette, unless given
    // Shown in the legend instead of one entry per series (their points are not drawn): a colour
    // per wavelength and a line style per section keep a legend short.
    std::vector<PlotSeries> legend;
    std::string note;                // drawn across the plot area ("no ray reaches the image plane")
    int width = 480, height = 300;   // user units; the SVG scales to its container
};

// The <svg> element for the plot.
std::string svgPlot(const Plot& plot);

}  // namespace lenslab
