#include "LensOutline.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

constexpr int kArcSteps = 64;

// Heights from -edge to +edge, with the rims of both surfaces exactly on the list.
std::vector<double> sampleHeights(double edge, double rimA, double rimB) {
    std::vector<double> h;
    for (int i = 0; i <= kArcSteps; ++i) h.push_back(-edge + 2 * edge * i / kArcSteps);
    for (double rim : {rimA, rimB}) {
        h.push_back(rim);
        h.push_back(-rim);
    }
    std::sort(h.begin(), h.end());
    h.erase(std::unique(h.begin(), h.end()), h.end());
    return h;
}

// The surface's z at height y; beyond its clear aperture it continues flat from the rim.
double profileZ(const Surface& s, double y) { return s.z - sag(s, std::min(std::abs(y), s.apertureRadius)); }

std::vector<ZY> arc(const Surface& s) {
    std::vector<ZY> points;
    for (double y : sampleHeights(s.apertureRadius, s.apertureRadius, s.apertureRadius)) points.push_back({profileZ(s, y), y});
    return points;
}

GlassElement element(const Surface& front, const Surface& rear, std::vector<std::vector<ZY>>& lines) {
    const double edge = std::max(front.apertureRadius, rear.apertureRadius);
    GlassElement g;
    g.index = front.indexAfter;
    for (double y : sampleHeights(edge, front.apertureRadius, rear.apertureRadius)) {
        g.front.push_back({profileZ(front, y), y});
        g.rear.push_back({profileZ(rear, y), y});
    }
    for (const Surface* s : {&front, &rear}) {
        if (s->apertureRadius >= edge) continue;
        const double zRim = profileZ(*s, edge);
        lines.push_back({{zRim, s->apertureRadius}, {zRim, edge}});
        lines.push_back({{zRim, -s->apertureRadius}, {zRim, -edge}});
    }
    for (double y : {edge, -edge}) lines.push_back({{profileZ(front, y), y}, {profileZ(rear, y), y}});
    return g;
}

}  // namespace

LensOutline buildLensOutline(const LensSystem& lens) {
    LensOutline out;
    const int n = static_cast<int>(lens.surfaces.size());
    for (int i = 0; i < n; ++i) {
        const Surface& s = lens.surfaces[i];
        out.maxRadius = std::max(out.maxRadius, s.apertureRadius);
        if (s.obscurationRadius > 0) out.obscurations.push_back({s.z - sag(s, s.obscurationRadius), s.obscurationRadius});
        // A stop on a flat surface between two airs is a diaphragm only: the blades show it.
        if (s.isStop && s.vertexCurvature() == 0 && !s.mirror && s.indexAfter == lens.indexBefore(i)) continue;
        (s.mirror ? out.mirrors : out.lines).push_back(arc(s));
        if (s.indexAfter != 1.0 && i + 1 < n) out.glass.push_back(element(s, lens.surfaces[i + 1], out.lines));
    }
    // The blades reach past the neighbouring elements so the stop reads as a diaphragm.
    const Surface& stop = lens.stop();
    double around = stop.apertureRadius;
    for (int i : {lens.stopIndex - 1, lens.stopIndex + 1})
        if (i >= 0 && i < n) around = std::max(around, lens.surfaces[i].apertureRadius);
    out.stop = {stop.z, stop.apertureRadius, 1.12 * around};
    out.maxRadius = std::max(out.maxRadius, out.stop.outerRadius);
    return out;
}

}  // namespace lenslab
