#include "analysis/SlantedEdgeSfr.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

constexpr double kBin = 0.25;  // pixels: four bins a pixel
constexpr double kMinSlantDegrees = 1, kMaxSlantDegrees = 30;

void fail(const std::string& problem) { throw std::invalid_argument("slanted edge: " + problem); }

// The region with the edge crossing its rows: values(x, y) varies along x.
struct Rows {
    int width = 0, height = 0;
    std::vector<double> v;
    double at(int x, int y) const { return v[std::size_t(y) * width + x]; }
};

Rows acrossRows(const PixelRegion& r, bool transpose) {
    Rows out{transpose ? r.height : r.width, transpose ? r.width : r.height, {}};
    out.v.resize(r.values.size());
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const double value = r.values[std::size_t(y) * r.width + x];
            if (transpose) out.v[std::size_t(x) * out.width + y] = value;
            else out.v[std::size_t(y) * out.width + x] = value;
        }
    return out;
}

// The sum of |differences| along x and along y: the edge lies across the larger.
bool edgeAcrossRows(const PixelRegion& r) {
    double alongX = 0, alongY = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const double v = r.values[std::size_t(y) * r.width + x];
            if (x + 1 < r.width) alongX += std::abs(r.values[std::size_t(y) * r.width + x + 1] - v);
            if (y + 1 < r.height) alongY += std::abs(r.values[std::size_t(y + 1) * r.width + x] - v);
        }
    return alongX >= alongY;
}

struct Line {
    double a = 0, b = 0;  // the edge crosses row y (centre y + 0.5) at x = a + b (y + 0.5), pixel-centre coordinates
    double at(double yCentre) const { return a + b * yCentre; }
};

// Each row's centroid of its differences (at x + 1, between the centres x + 0.5 and x + 1.5),
// under a Hamming window around `around` when given; then the least-squares line through them.
Line fitEdge(const Rows& r, const Line* around) {
    double sy = 0, sx = 0, syy = 0, sxy = 0;
    double range = 0;
    for (double v : r.v) range = std::max(range, std::abs(v - r.v.front()));
    const double halfWidth = 0.5 * r.width;
    for (int y = 0; y < r.height; ++y) {
        double sum = 0, moment = 0;
        for (int x = 0; x + 1 < r.width; ++x) {
            double d = r.at(x + 1, y) - r.at(x, y);
            if (around) {
                const double u = (x + 1 - around->at(y + 0.5)) / halfWidth;
                d *= std::abs(u) < 1 ? 0.54 + 0.46 * std::cos(kPi * u) : 0.0;
            }
            sum += d;
            moment += d * (x + 1);
        }
        if (!(std::abs(sum) > 0.2 * range)) fail("row " + std::to_string(y) + " has no step across it");
        const double centroid = moment / sum, yc = y + 0.5;
        sy += yc, sx += centroid, syy += yc * yc, sxy += yc * centroid;
    }
    const double n = r.height, det = n * syy - sy * sy;
    Line line;
    line.b = (n * sxy - sy * sx) / det;
    line.a = (sx - line.b * sy) / n;
    return line;
}

// The edge spread function in bins kBin wide along the normal, centred at k kBin for k in
// [first, first + size): every bin holds pixels of every row, so an empty one (a slant that leaves
// a phase out) is filled from its neighbours.
struct Spread {
    int first = 0;
    std::vector<double> values;
};

Spread binAlongNormal(const Rows& r, const Line& line, int rowBegin, int rowEnd) {
    const double cosine = 1 / std::sqrt(1 + line.b * line.b);
    double lo = -1e300, hi = 1e300;
    for (int y = rowBegin; y < rowEnd; ++y) {
        const double edge = line.at(y + 0.5);
        lo = std::max(lo, (0.5 - edge) * cosine);
        hi = std::min(hi, (r.width - 0.5 - edge) * cosine);
    }
    Spread s;
    s.first = int(std::ceil(lo / kBin + 0.5));
    const int last = int(std::floor(hi / kBin - 0.5));
    if (last - s.first < 16) fail("too narrow: the edge needs pixels on both sides of it");
    std::vector<double> sum(last - s.first + 1, 0.0);
    std::vector<int> count(sum.size(), 0);
    for (int y = rowBegin; y < rowEnd; ++y)
        for (int x = 0; x < r.width; ++x) {
            const int k = int(std::floor((x + 0.5 - line.at(y + 0.5)) * cosine / kBin + 0.5)) - s.first;
            if (k < 0 || k >= int(sum.size())) continue;
            sum[k] += r.at(x, y);
            ++count[k];
        }
    s.values.assign(sum.size(), 0.0);
    for (std::size_t k = 0; k < sum.size(); ++k) {
        if (count[k] > 0) {
            s.values[k] = sum[k] / count[k];
            continue;
        }
        std::size_t before = k, after = k;
        while (before > 0 && count[before] == 0) --before;
        while (after + 1 < sum.size() && count[after] == 0) ++after;
        if (count[before] == 0 && count[after] == 0) fail("no pixel fell in the edge's bins");
        s.values[k] = count[before] == 0 ? sum[after] / count[after]
                    : count[after] == 0  ? sum[before] / count[before]
                                         : 0.5 * (sum[before] / count[before] + sum[after] / count[after]);
    }
    return s;
}

}  // namespace

EdgeSfr slantedEdgeSfr(const PixelRegion& region, const std::vector<double>& cyclesPerPixel) {
    if (region.width < 8 || region.height < 8 || region.values.size() != std::size_t(region.width) * region.height)
        fail("the region must be at least 8 x 8 pixels with one value each");
    for (double v : region.values)
        if (!std::isfinite(v)) fail("a pixel value is not finite");
    for (double f : cyclesPerPixel)
        if (!(f >= 0 && f <= 1)) fail("frequencies must lie in 0-1 cycles per pixel");

    EdgeSfr out;
    out.alongRows = edgeAcrossRows(region);
    const Rows rows = acrossRows(region, !out.alongRows);
    const Line rough = fitEdge(rows, nullptr);
    const Line line = fitEdge(rows, &rough);
    const double slant = std::atan(line.b) * 180 / kPi;
    if (std::abs(slant) < kMinSlantDegrees || std::abs(slant) > kMaxSlantDegrees)
        fail("the edge is slanted " + std::to_string(slant) + " degrees; 1 to 30 are needed (about 5 is best)");
    // Whole turns of the phase, so that every quarter-pixel bin is filled alike.
    const int turns = int(std::floor(rows.height * std::abs(line.b)));
    if (turns < 1) fail("too few rows for one whole turn of the edge's phase across the pixels");
    out.rowsUsed = std::min(rows.height, int(std::ceil(turns / std::abs(line.b) - 1e-9)));
    const int rowBegin = (rows.height - out.rowsUsed) / 2;
    const Spread spread = binAlongNormal(rows, line, rowBegin, rowBegin + out.rowsUsed);

    // The line spread function by central differences at the bins' centres; its sign makes the
    // normal point from dark to bright.
    const std::vector<double>& e = spread.values;
    std::vector<double> lsf(e.size(), 0.0), at(e.size(), 0.0);
    double total = 0, moment = 0;
    for (std::size_t k = 1; k + 1 < e.size(); ++k) {
        lsf[k] = 0.5 * (e[k + 1] - e[k - 1]);
        at[k] = (spread.first + double(k)) * kBin;
        total += lsf[k];
    }
    const double sign = total < 0 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < lsf.size(); ++k) lsf[k] *= sign, moment += lsf[k] * at[k];
    const double centre = moment / (sign * total);
    const double halfWindow = 0.5 * (e.size() - 2) * kBin;
    for (std::size_t k = 1; k + 1 < e.size(); ++k) {
        const double u = (at[k] - centre) / halfWindow;
        lsf[k] *= std::abs(u) < 1 ? 0.54 + 0.46 * std::cos(kPi * u) : 0.0;
    }
    double dc = 0;
    for (double l : lsf) dc += l;
    if (!(dc > 0)) fail("the line spread function has no area");

    for (double f : cyclesPerPixel) {
        std::complex<double> sum = 0;
        for (std::size_t k = 1; k + 1 < e.size(); ++k) sum += lsf[k] * std::polar(1.0, -2 * kPi * f * at[k]);
        // The central difference over two bins passes sin(2 pi f kBin) / (2 pi f kBin) of a derivative.
        const double x = 2 * kPi * f * kBin;
        out.sfr.push_back(std::abs(sum) / dc / (x > 0 ? std::sin(x) / x : 1.0));
    }
    out.frequencies = cyclesPerPixel;

    const double cosine = 1 / std::sqrt(1 + line.b * line.b);
    const double nx = sign * cosine, ny = -sign * line.b * cosine;  // normal in the rows' frame (x across)
    const double midY = 0.5 * rows.height, midX = line.at(midY);
    out.angleDegrees = slant;
    out.normalX = out.alongRows ? nx : ny;
    out.normalY = out.alongRows ? ny : nx;
    out.centreX = out.alongRows ? midX : midY;
    out.centreY = out.alongRows ? midY : midX;
    return out;
}

}  // namespace lenslab
