#include "LensOutline.h"

#include <algorithm>
#include <cmath>

#include "MirrorSolids.h"

namespace lenslab {

double profileZ(const Surface& s, double y) { return s.z - sag(s, std::min(std::abs(y), s.apertureRadius)); }

namespace {

constexpr int kArcSteps = 64;

// The height ranges a surface or element is drawn over: the whole of [-edge, edge], or the two
// pieces outside a bore.
std::vector<std::pair<double, double>> drawnSpans(double bore, double edge) {
    if (bore > 0) return {{-edge, -bore}, {bore, edge}};
    return {{-edge, edge}};
}

// Heights from low to high, with the rims of both surfaces exactly on the list where they fall inside.
std::vector<double> sampleHeights(double low, double high, double rimA, double rimB) {
    std::vector<double> h;
    for (int i = 0; i <= kArcSteps; ++i) h.push_back(low + (high - low) * i / kArcSteps);
    for (double rim : {rimA, rimB, -rimA, -rimB})
        if (rim > low && rim < high) h.push_back(rim);
    std::sort(h.begin(), h.end());
    h.erase(std::unique(h.begin(), h.end()), h.end());
    return h;
}

std::vector<std::vector<ZY>> arcs(const Surface& s, double bore) {
    std::vector<std::vector<ZY>> pieces;
    for (const auto& [low, high] : drawnSpans(bore, s.apertureRadius)) {
        pieces.emplace_back();
        for (double y : sampleHeights(low, high, s.apertureRadius, s.apertureRadius)) pieces.back().push_back({profileZ(s, y), y});
    }
    return pieces;
}

void addElement(const Surface& front, const Surface& rear, double bore, LensOutline& out) {
    const double edge = std::max(front.apertureRadius, rear.apertureRadius);
    for (const auto& [low, high] : drawnSpans(bore, edge)) {
        GlassElement g;
        g.index = front.indexAfter;
        for (double y : sampleHeights(low, high, front.apertureRadius, rear.apertureRadius)) {
            g.front.push_back({profileZ(front, y), y});
            g.rear.push_back({profileZ(rear, y), y});
        }
        out.glass.push_back(std::move(g));
    }
    for (const Surface* s : {&front, &rear}) {
        if (s->apertureRadius >= edge) continue;
        const double zRim = profileZ(*s, edge);
        out.lines.push_back({{zRim, s->apertureRadius}, {zRim, edge}});
        out.lines.push_back({{zRim, -s->apertureRadius}, {zRim, -edge}});
    }
    // The element's edges, and the bore's walls.
    for (double y : {edge, -edge}) out.lines.push_back({{profileZ(front, y), y}, {profileZ(rear, y), y}});
    if (bore > 0)
        for (double y : {bore, -bore}) out.lines.push_back({{profileZ(front, y), y}, {profileZ(rear, y), y}});
}

}  // namespace

LensOutline buildLensOutline(const LensSystem& lens) { return buildLensOutline(lens, MirrorBores{}); }

LensOutline buildLensOutline(const LensSystem& lens, const MirrorBores& bores) {
    LensOutline out;
    const int n = static_cast<int>(lens.surfaces.size());
    for (int i = 0; i < n; ++i) {
        const Surface& s = lens.surfaces[i];
        out.maxRadius = std::max(out.maxRadius, s.apertureRadius);
        if (s.obscurationRadius > 0 && !s.mirror) out.obscurations.push_back({s.z - sag(s, s.obscurationRadius), s.obscurationRadius});
        // A stop on a flat surface between two airs is a diaphragm only: the blades show it.
        if (s.isStop && s.vertexCurvature() == 0 && !s.mirror && s.indexAfter == lens.indexBefore(i)) continue;
        for (auto& piece : arcs(s, bores.at(i))) (s.mirror ? out.mirrors : out.lines).push_back(std::move(piece));
        if (s.indexAfter != 1.0 && i + 1 < n) addElement(s, lens.surfaces[i + 1], std::max(bores.at(i), bores.at(i + 1)), out);
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
