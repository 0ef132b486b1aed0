#include "SvgPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "MarkupText.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

// Okabe & Ito's palette (distinguishable with the common colour-vision deficiencies), minus yellow.
const char* const kPalette[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000", "#7f7f7f"};
constexpr int kPaletteSize = sizeof kPalette / sizeof kPalette[0];

constexpr double kFontSize = 12, kCharWidth = 7.2;  // average glyph advance of a sans-serif at 12 px
constexpr double kTop = 30, kLeft = 62, kRight = 16, kAxisBand = 42, kLegendRow = 18;

std::string num(double v) { return formatFixed(v, 2); }

struct Scale {
    bool log = false;
    double lo = 0, hi = 1;          // data range shown
    double pixelLo = 0, pixelHi = 1;
    std::vector<double> ticks;
    int decimals = 0;               // linear tick labels

    double operator()(double v) const {
        const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
        return pixelLo + t * (pixelHi - pixelLo);
    }
    bool shows(double v) const { return std::isfinite(v) && (!log || v > 0); }
    std::string label(double v) const {
        return log ? formatNumber(v) : formatFixed(v, decimals);
    }
};

// 1, 2, 2.5 or 5 times a power of ten, near `rough`.
double niceStep(double rough) {
    const double p = std::pow(10.0, std::floor(std::log10(rough)));
    const double m = rough / p;
    return (m < 1.5 ? 1 : m < 2.2 ? 2 : m < 3.5 ? 2.5 : m < 7.5 ? 5 : 10) * p;
}

// About `intervals` linear ticks (log axes tick their decades).
Scale makeScale(const PlotAxis& axis, const std::vector<double>& values, double pixelLo, double pixelHi, int intervals = 5) {
    Scale s;
    s.log = axis.logarithmic;
    s.pixelLo = pixelLo;
    s.pixelHi = pixelHi;
    double lo = values.empty() ? (s.log ? 1 : 0) : *std::min_element(values.begin(), values.end());
    double hi = values.empty() ? (s.log ? 10 : 1) : *std::max_element(values.begin(), values.end());
    if (s.log) {
        s.lo = axis.min.value_or(std::pow(10.0, std::floor(std::log10(lo))));
        s.hi = axis.max.value_or(std::pow(10.0, std::ceil(std::log10(hi))));
        if (!(s.hi > s.lo)) s.hi = s.lo * 10;
        const bool fewDecades = std::log10(s.hi / s.lo) <= 2.01;
        for (double decade = std::pow(10.0, std::floor(std::log10(s.lo))); decade <= s.hi * 1.0001; decade *= 10)
            for (double m : {1.0, 2.0, 5.0})
                if ((m == 1.0 || fewDecades) && decade * m >= s.lo * 0.9999 && decade * m <= s.hi * 1.0001)
                    s.ticks.push_back(decade * m);
        return s;
    }
    if (lo > 0 && lo < 0.25 * hi) lo = 0;
    if (hi < 0 && hi > 0.25 * lo) hi = 0;
    lo = axis.min.value_or(lo);
    hi = axis.max.value_or(hi);
    if (!(hi > lo)) {
        const double pad = lo == 0 ? 1 : 0.1 * std::fabs(lo);
        lo -= pad;
        hi += pad;
    }
    const double step = niceStep((hi - lo) / intervals);
    s.lo = axis.min ? lo : std::floor(lo / step + 1e-9) * step;
    s.hi = axis.max ? hi : std::ceil(hi / step - 1e-9) * step;
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
    s.decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)) + (std::fabs(mantissa - 2.5) < 1e-9 ? 1 : 0));
    for (double t = std::ceil(s.lo / step - 1e-9) * step; t <= s.hi + 1e-9 * step; t += step)
        s.ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
    return s;
}

double textWidth(const std::string& text) { return kCharWidth * text.size(); }

bool labelsCollide(const Scale& s) {
    for (std::size_t i = 1; i < s.ticks.size(); ++i)
        if (std::fabs(s(s.ticks[i]) - s(s.ticks[i - 1])) < 0.5 * (textWidth(s.label(s.ticks[i])) + textWidth(s.label(s.ticks[i - 1]))) + 8)
            return true;
    return false;
}

double legendEntryWidth(const PlotSeries& s) { return 28 + textWidth(s.label) + 14; }

std::string seriesColour(const PlotSeries& s, std::size_t index) {
    return s.colour.empty() ? kPalette[index % kPaletteSize] : s.colour;
}

const char* dashAttribute(LineDash dash) {
    return dash == LineDash::Dashed ? " stroke-dasharray=\"6 4\"" : dash == LineDash::Dotted ? " stroke-dasharray=\"1.5 3\" stroke-linecap=\"round\"" : "";
}

// The legend's entries: the plot's own, else one per series when there are several.
std::vector<PlotSeries> legendEntries(const Plot& plot) {
    std::vector<PlotSeries> entries = !plot.legend.empty() ? plot.legend
                                      : plot.series.size() > 1 ? plot.series
                                                               : std::vector<PlotSeries>{};
    for (std::size_t i = 0; i < entries.size(); ++i) entries[i].colour = seriesColour(entries[i], i);
    return entries;
}

// Entry indices per legend row, filling rows up to `width`.
std::vector<std::vector<std::size_t>> legendRows(const std::vector<PlotSeries>& entries, double width) {
    std::vector<std::vector<std::size_t>> rows;
    double used = 0;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const double w = legendEntryWidth(entries[i]);
        if (rows.empty() || (used > 0 && used + w > width)) {
            rows.emplace_back();
            used = 0;
        }
        rows.back().push_back(i);
        used += w;
    }
    return rows;
}

void drawSeries(std::ostringstream& out, const PlotSeries& s, const std::string& colour, const Scale& x, const Scale& y) {
    const bool line = s.style != SeriesStyle::Markers, markers = s.style != SeriesStyle::Line;
    if (line) {
        std::string d;
        bool pen = false;
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!x.shows(s.x[i]) || !y.shows(s.y[i])) {
                pen = false;
                continue;
            }
            d += (pen ? " L" : " M") + num(x(s.x[i])) + " " + num(y(s.y[i]));
            pen = true;
        }
        if (!d.empty())
            out << "<path d=\"" << d.substr(1) << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\""
                << dashAttribute(s.dash) << " stroke-linejoin=\"round\"/>\n";
    }
    if (markers)
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
            if (x.shows(s.x[i]) && y.shows(s.y[i]))
                out << "<circle cx=\"" << num(x(s.x[i])) << "\" cy=\"" << num(y(s.y[i])) << "\" r=\"" << num(s.markerRadius) << "\" fill=\""
                    << colour << "\"/>\n";
}

}  // namespace

std::string svgPlot(const Plot& plot) {
    const double plotRight = plot.width - kRight;
    const std::vector<PlotSeries> entries = legendEntries(plot);
    const auto legend = legendRows(entries, plotRight - kLeft);
    const double height = plot.height + kLegendRow * legend.size();
    const double plotBottom = plot.height - kAxisBand;
    // Ranges from the points that will be drawn: both coordinates finite (and positive on a log axis).
    std::vector<double> xs, ys;
    for (const PlotSeries& s : plot.series)
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
            if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!plot.x.logarithmic || s.x[i] > 0) &&
                (!plot.y.logarithmic || s.y[i] > 0)) {
                xs.push_back(s.x[i]);
                ys.push_back(s.y[i]);
            }
    // Fewer x ticks where their labels would touch (long decimals on a narrow plot).
    Scale x = makeScale(plot.x, xs, kLeft, plotRight);
    for (int intervals = 4; intervals >= 1 && labelsCollide(x); --intervals) x = makeScale(plot.x, xs, kLeft, plotRight, intervals);
    const Scale y = makeScale(plot.y, ys, plotBottom, kTop);

    std::ostringstream out;
    const std::string titleId = plot.id + "-title";
    // The namespace makes the markup a valid .svg file as well as inline SVG (lenslab analyze -o).
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" viewBox=\"0 0 " << plot.width << " " << num(height)
        << "\" width=\"" << plot.width << "\" height=\"" << num(height) << "\" role=\"img\" aria-labelledby=\"" << titleId
        << "\" font-family=\"system-ui, sans-serif\" font-size=\"" << kFontSize << "\">\n";
    out << "<title id=\"" << titleId << "\">" << escapeMarkup(plot.title) << "</title>\n";
    out << "<defs><clipPath id=\"" << plot.id << "-area\"><rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\""
        << num(plotRight - kLeft) << "\" height=\"" << num(plotBottom - kTop) << "\"/></clipPath></defs>\n";
    out << "<text x=\"" << kLeft << "\" y=\"18\" font-weight=\"600\">" << escapeMarkup(plot.title) << "</text>\n";

    // Grid and tick labels.
    for (double t : x.ticks) {
        const std::string px = num(x(t));
        out << "<line x1=\"" << px << "\" y1=\"" << kTop << "\" x2=\"" << px << "\" y2=\"" << num(plotBottom)
            << "\" stroke=\"#e3e3e3\"/>\n<text x=\"" << px << "\" y=\"" << num(plotBottom + 16)
            << "\" text-anchor=\"middle\" fill=\"#333\">" << x.label(t) << "</text>\n";
    }
    for (double t : y.ticks) {
        const std::string py = num(y(t));
        out << "<line x1=\"" << kLeft << "\" y1=\"" << py << "\" x2=\"" << num(plotRight) << "\" y2=\"" << py
            << "\" stroke=\"#e3e3e3\"/>\n<text x=\"" << kLeft - 6 << "\" y=\"" << py
            << "\" dy=\"0.35em\" text-anchor=\"end\" fill=\"#333\">" << y.label(t) << "</text>\n";
    }
    if (!y.log && y.lo < 0 && y.hi > 0)
        out << "<line x1=\"" << kLeft << "\" y1=\"" << num(y(0)) << "\" x2=\"" << num(plotRight) << "\" y2=\""
            << num(y(0)) << "\" stroke=\"#888\"/>\n";
    out << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << num(plotRight - kLeft) << "\" height=\""
        << num(plotBottom - kTop) << "\" fill=\"none\" stroke=\"#555\"/>\n";

    // Axis labels.
    out << "<text x=\"" << num(0.5 * (kLeft + plotRight)) << "\" y=\"" << num(plotBottom + 34)
        << "\" text-anchor=\"middle\">" << escapeMarkup(plot.x.label) << "</text>\n";
    out << "<text transform=\"translate(14 " << num(0.5 * (kTop + plotBottom)) << ") rotate(-90)\" text-anchor=\"middle\">"
        << escapeMarkup(plot.y.label) << "</text>\n";

    out << "<g clip-path=\"url(#" << plot.id << "-area)\">\n";
    for (std::size_t i = 0; i < plot.series.size(); ++i) drawSeries(out, plot.series[i], seriesColour(plot.series[i], i), x, y);
    out << "</g>\n";
    if (!plot.note.empty())
        out << "<text x=\"" << num(0.5 * (kLeft + plotRight)) << "\" y=\"" << num(0.5 * (kTop + plotBottom))
            << "\" text-anchor=\"middle\" fill=\"#b42318\">" << escapeMarkup(plot.note) << "</text>\n";

    // Legend: swatch and label per series, in rows under the axis label.
    for (std::size_t r = 0; r < legend.size(); ++r) {
        double lx = kLeft;
        const double ly = plot.height + r * kLegendRow + 2;
        for (std::size_t i : legend[r]) {
            const PlotSeries& s = entries[i];
            if (s.style == SeriesStyle::Markers)
                out << "<circle cx=\"" << num(lx + 11) << "\" cy=\"" << num(ly) << "\" r=\"3.5\" fill=\"" << s.colour << "\"/>\n";
            else
                out << "<line x1=\"" << num(lx) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(lx + 22) << "\" y2=\""
                    << num(ly) << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"" << dashAttribute(s.dash) << "/>\n";
            out << "<text x=\"" << num(lx + 28) << "\" y=\"" << num(ly) << "\" dy=\"0.35em\"";
            for (const auto& [name, value] : s.labelAttributes) out << " " << name << "=\"" << escapeMarkup(value) << "\"";
            out << ">" << escapeMarkup(s.label) << "</text>\n";
            lx += legendEntryWidth(s);
        }
    }
    out << "</svg>";
    return out.str();
}

}  // namespace lenslab
