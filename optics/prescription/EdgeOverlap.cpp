#include "prescription/EdgeOverlap.h"

#include <algorithm>
#include <cmath>

#include "prescription/NumberText.h"

namespace lenslab {

namespace {

// How far surface b lies beyond surface a at height h, along the light (negative: they cross).
double clearance(const Surface& a, const Surface& b, double h, double way) {
    return way * ((a.z - sag(a, h)) - (b.z - sag(b, h)));
}

}  // namespace

void clipOverlappingEdges(LensSystem& lens) {
    const int n = static_cast<int>(lens.surfaces.size());
    for (int i = 0; i + 1 < n; ++i) {
        Surface& a = lens.surfaces[i];
        Surface& b = lens.surfaces[i + 1];
        // Decentred, tilted and shaped surfaces do not face each other across a common axis.
        if (a.isMoved() || b.isMoved() || a.clearShape || b.clearShape) continue;
        const double way = -lens.zDirectionAfter(i);  // +1 while the light travels toward the film
        const double hMax = std::min(a.apertureRadius, b.apertureRadius);
        const double tolerance = 1e-9 * std::max(1.0, std::fabs(a.z));
        constexpr int kSamples = 64;
        double inside = 0;  // the largest height found clear
        bool crosses = false;
        for (int k = 0; k <= kSamples && !crosses; ++k) {
            const double h = hMax * k / kSamples;
            if (clearance(a, b, h, way) < -tolerance) crosses = true;
            else inside = h;
        }
        if (!crosses) continue;
        if (inside == 0 && clearance(a, b, 0, way) < -tolerance)
            throw LensTableError(lens.name, b.line, "surface overlaps the one before it (line " + std::to_string(a.line) +
                                                        ") on the axis: gap " + formatMillimetres(way * (a.z - b.z)));
        double outside = hMax * std::min(1.0, (inside / hMax) + 1.0 / kSamples);
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (inside + outside);
            (clearance(a, b, mid, way) < -tolerance ? outside : inside) = mid;
        }
        if (!a.automaticAperture || !b.automaticAperture) {
            const double edge = clearance(a, b, hMax, way);
            lens.warnings.push_back(
                {b.line, "surfaces on lines " + std::to_string(a.line) + " and " + std::to_string(b.line) +
                             " cross at height " + formatMillimetres(inside) + ", inside their clear apertures (edge thickness " +
                             formatMillimetres(edge) + " at " + formatMillimetres(hMax) + "): rays beyond " + formatMillimetres(inside) + " are clipped there"});
        }
        a.apertureRadius = std::min(a.apertureRadius, inside);
        b.apertureRadius = std::min(b.apertureRadius, inside);
    }
}

}  // namespace lenslab
