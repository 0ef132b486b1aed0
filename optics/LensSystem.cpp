#include "LensSystem.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lenslab {

namespace {

std::string mm(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v << " mm";
    return s.str();
}

// Surfaces i and i+1 must not cross anywhere both exist; touching at a rim is allowed.
void checkNoOverlap(const LensSystem& lens, const std::vector<LensTableRow>& rows, int i) {
    const Surface& a = lens.surfaces[i];
    const Surface& b = lens.surfaces[i + 1];
    const double hMax = std::min(a.apertureRadius, b.apertureRadius);
    const double tolerance = 1e-9 * std::max(1.0, std::fabs(a.z));
    constexpr int kSamples = 64;
    for (int k = 0; k <= kSamples; ++k) {
        const double h = hMax * k / kSamples;
        const double zA = a.z - sag(a, h), zB = b.z - sag(b, h);
        if (zA < zB - tolerance) {
            std::ostringstream msg;
            msg << "surface overlaps the one before it: at height " << mm(h) << " its sag puts it "
                << mm(zB - zA) << " in front of line " << rows[i].line << "'s surface (gap "
                << mm(a.z - b.z) << ")";
            throw LensTableError(lens.name, rows[i + 1].line, msg.str());
        }
    }
}

}  // namespace

double sag(const Surface& s, double h) {
    // Written so that flat surfaces (curvature 0) and huge radii stay exact.
    const double c = s.curvature;
    return c * h * h / (1.0 + std::sqrt(std::max(0.0, 1.0 - c * c * h * h)));
}

LensSystem buildLensSystem(const LensTable& table) {
    LensSystem lens;
    lens.name = table.name;
    lens.comments = table.comments;
    lens.layout = table.layout;
    const auto& rows = table.rows;
    const int n = static_cast<int>(rows.size());

    int stops = 0;
    double z = 0;
    for (int i = 0; i < n; ++i) {
        const LensTableRow& r = rows[i];
        if (table.layout == TableLayout::GapBefore) z -= r.gap;
        else if (i > 0) z -= rows[i - 1].gap;
        Surface s;
        s.z = z;
        s.radius = r.radius;
        s.curvature = r.radius == 0 ? 0.0 : 1.0 / r.radius;
        s.indexAfter = r.index == 0 ? 1.0 : r.index;
        s.apertureRadius = 0.5 * r.diameter;
        s.isStop = r.isStop();
        s.line = r.line;
        if (s.isStop) {
            if (++stops > 1)
                throw LensTableError(table.name, r.line,
                                     "a second aperture stop (radius 0, N 0); the first is on line " +
                                         std::to_string(rows[lens.stopIndex].line));
            lens.stopIndex = i;
        }
        if (r.radius != 0 && s.apertureRadius > std::fabs(r.radius))
            throw LensTableError(table.name, r.line,
                                 "diameter " + mm(r.diameter) + " is larger than the sphere of radius " +
                                     mm(std::fabs(r.radius)) + " allows (at most " +
                                     mm(2 * std::fabs(r.radius)) + ")");
        lens.surfaces.push_back(s);
    }
    if (stops == 0)
        throw LensTableError(table.name, rows.front().line,
                             "no aperture stop: one row must have radius 0 and N 0");
    if (lens.surfaces.back().indexAfter != 1.0)
        throw LensTableError(table.name, rows.back().line,
                             "the last surface must leave the ray in air (N 0 or 1) before the film");
    for (int i = 0; i + 1 < n; ++i) checkNoOverlap(lens, rows, i);
    return lens;
}

LensSystem loadLensSystem(const std::string& path, std::optional<TableLayout> layout) {
    return buildLensSystem(readLensTable(path, layout));
}

LensSystem withStopDiameter(const LensSystem& lens, double diameter) {
    LensSystem out = lens;
    out.surfaces[out.stopIndex].apertureRadius = 0.5 * diameter;
    return out;
}

}  // namespace lenslab
