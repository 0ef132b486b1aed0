#include "PanelPlot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "DiagramBackend.h"
#include "DrawList.h"
#include "GlCanvas.h"
#include "prescription/NumberText.h"
#include "PngCodec.h"
#include "TextRaster.h"

namespace lenslab::tradeoff {

namespace {

// Okabe-Ito: tells the series apart for colour-blind readers too.
const Rgba kPalette[] = {{0, 114, 178, 255}, {213, 94, 0, 255}, {0, 158, 115, 255}, {204, 121, 167, 255},
                         {230, 159, 0, 255}, {86, 180, 233, 255}};
const Rgba kInk{40, 40, 40, 255}, kGrid{225, 225, 225, 255}, kWhite{255, 255, 255, 255};

struct Axis {
    double lo = 0, hi = 1;
    bool log = false;
    double map(double v, double a, double b) const {  // data value to pixels a..b
        const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
        return a + t * (b - a);
    }
    std::vector<double> ticks() const {
        std::vector<double> t;
        if (log) {
            for (double d = std::pow(10.0, std::floor(std::log10(lo))); d <= hi * 1.0001; d *= 10)
                for (double m : {1.0, 2.0, 5.0})
                    if (m * d >= lo * 0.9999 && m * d <= hi * 1.0001) t.push_back(m * d);
            return t;
        }
        const double step = std::pow(10.0, std::floor(std::log10((hi - lo) / 4)));
        const double nice = (hi - lo) / step > 20 ? 5 * step : (hi - lo) / step > 8 ? 2 * step : step;
        for (double v = std::ceil(lo / nice) * nice; v <= hi + 1e-9 * nice; v += nice) t.push_back(v);
        return t;
    }
};

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

Axis fitAxis(const Panel& p, bool xAxis) {
    const bool log = xAxis ? p.logX : p.logY;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Series& s : p.series)
        for (double v : xAxis ? s.x : s.y)
            if (usable(v, log)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (!(lo <= hi)) lo = 1, hi = 10;
    Axis a;
    a.log = log;
    if (log) {
        a.lo = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
        a.hi = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
        if (a.hi <= a.lo) a.hi = a.lo * 10;
    } else {
        a.lo = std::min(0.0, lo);
        a.hi = hi > a.lo ? hi * 1.05 : a.lo + 1;
    }
    return a;
}

void drawPanel(const Panel& p, double left, double top, double width, double height, DrawList& list,
               std::vector<TextLabel>& labels) {
    const double x0 = left + 62, x1 = left + width - 16, y0 = top + 52, y1 = top + height - 52;
    const Axis ax = fitAxis(p, true), ay = fitAxis(p, false);
    labels.push_back({{(x0 + x1) / 2, top + 20}, p.title, 16, kInk, TextAnchor::Centre});  // the y label has its own line below
    for (double t : ax.ticks()) {
        const double x = ax.map(t, x0, x1);
        addLine(list, {x, y0}, {x, y1}, 1, kGrid);
        labels.push_back({{x, y1 + 17}, formatNumber(t), 12, kInk, TextAnchor::Centre});
    }
    for (double t : ay.ticks()) {
        const double y = ay.map(t, y1, y0);
        addLine(list, {x0, y}, {x1, y}, 1, kGrid);
        labels.push_back({{x0 - 6, y + 4}, formatNumber(t), 12, kInk, TextAnchor::Right});
    }
    addPolyline(list, {{x0, y0}, {x0, y1}, {x1, y1}}, 1.5, kInk);
    labels.push_back({{(x0 + x1) / 2, y1 + 36}, p.xLabel, 13, kInk, TextAnchor::Centre});
    labels.push_back({{x0 - 4, y0 - 10}, p.yLabel, 13, kInk, TextAnchor::Left});
    for (std::size_t i = 0; i < p.series.size(); ++i) {
        const Series& s = p.series[i];
        const Rgba colour = kPalette[i % std::size(kPalette)];
        std::vector<Point2> line;
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
            if (!usable(s.x[k], ax.log) || !usable(s.y[k], ay.log)) continue;
            const Point2 q{ax.map(s.x[k], x0, x1), ay.map(s.y[k], y1, y0)};
            line.push_back(q);
            addDisc(list, q, 3.2, colour);
        }
        if (s.dashed) addDashedPolyline(list, line, 2, 7, 5, colour);
        else addPolyline(list, line, 2, colour);
        // The legend, top right, one row per series.
        const double ly = y0 + 14 + 18 * i;
        addLine(list, {x1 - 150, ly - 4}, {x1 - 128, ly - 4}, 2.5, colour);
        labels.push_back({{x1 - 122, ly}, s.label, 12, kInk, TextAnchor::Left});
    }
}

}  // namespace

std::vector<unsigned char> drawPanelsPng(const std::vector<Panel>& panels, int columns, int panelWidth, int panelHeight) {
    const int rows = (int(panels.size()) + columns - 1) / columns;
    const int width = columns * panelWidth, height = rows * panelHeight;
    DrawList list;
    std::vector<TextLabel> labels;
    for (std::size_t i = 0; i < panels.size(); ++i)
        drawPanel(panels[i], double(i % columns) * panelWidth, double(i / columns) * panelHeight, panelWidth, panelHeight,
                  list, labels);
    const auto backend = createDiagramBackend(DiagramBackendKind::OSMesa);
    backend->makeCurrent();
    GlCanvas canvas;
    std::vector<std::uint8_t> pixels = canvas.rasterise(list, width, height, kWhite);
    drawTextLabels(pixels, width, height, labels, kWhite);
    return encodePngRgba8(width, height, pixels.data());
}

}  // namespace lenslab::tradeoff
