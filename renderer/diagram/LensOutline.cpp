#include "LensOutline.h"

#include <algorithm>
#include <cmath>

#include "MirrorSolids.h"
#include "trace/ExactTrace.h"

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

// Where each surface lies in the coordinates the rays are drawn in (object space, as the trace
// records a path): its own frame carried back through every motion before it. A tilted plate is
// drawn tilted, a fold mirror across the fold. The identity for a lens whose surfaces never move.
std::vector<RigidMotion> surfacePlacements(const LensSystem& lens) {
    std::vector<RigidMotion> placed;
    RigidMotion toStart;
    for (const Surface& s : lens.surfaces) {
        if (const RigidMotion into = motionInto(s, TraceDirection::SceneToFilm); !into.isIdentity())
            toStart = into.inverse().then(toStart);
        placed.push_back(toStart);
        if (const RigidMotion out = motionOutOf(s, TraceDirection::SceneToFilm); !out.isIdentity())
            toStart = out.inverse().then(toStart);
    }
    return placed;
}

// A point of a surface's profile (height y in its meridional plane) where the drawing shows it.
ZY placedPoint(const RigidMotion& placement, const Surface& s, double y) {
    if (placement.isIdentity()) return {profileZ(s, y), y};
    const auto p = placement.applyToPoint({0, y, profileZ(s, y)});
    return {p[2], p[1]};
}

std::vector<std::vector<ZY>> arcs(const Surface& s, const RigidMotion& placement, double bore) {
    std::vector<std::vector<ZY>> pieces;
    for (const auto& [low, high] : drawnSpans(bore, s.apertureRadius)) {
        pieces.emplace_back();
        for (double y : sampleHeights(low, high, s.apertureRadius, s.apertureRadius))
            pieces.back().push_back(placedPoint(placement, s, y));
    }
    return pieces;
}

struct PlacedSurface {
    const Surface& surface;
    const RigidMotion& placement;
    ZY at(double y) const { return placedPoint(placement, surface, y); }
};

void addElement(const PlacedSurface& front, const PlacedSurface& rear, double bore, LensOutline& out) {
    const double edge = std::max(front.surface.apertureRadius, rear.surface.apertureRadius);
    for (const auto& [low, high] : drawnSpans(bore, edge)) {
        GlassElement g;
        g.index = front.surface.indexAfter;
        for (double y : sampleHeights(low, high, front.surface.apertureRadius, rear.surface.apertureRadius)) {
            g.front.push_back(front.at(y));
            g.rear.push_back(rear.at(y));
        }
        out.glass.push_back(std::move(g));
    }
    for (const PlacedSurface* s : {&front, &rear}) {
        const double r = s->surface.apertureRadius;
        if (r >= edge) continue;
        // The flat step from the rim out to the element's edge (profileZ holds the rim's z beyond it).
        out.lines.push_back({s->at(r), s->at(edge)});
        out.lines.push_back({s->at(-r), s->at(-edge)});
    }
    // The element's edges, and the bore's walls.
    for (double y : {edge, -edge}) out.lines.push_back({front.at(y), rear.at(y)});
    if (bore > 0)
        for (double y : {bore, -bore}) out.lines.push_back({front.at(y), rear.at(y)});
}

}  // namespace

LensOutline buildLensOutline(const LensSystem& lens) { return buildLensOutline(lens, MirrorBores{}); }

LensOutline buildLensOutline(const LensSystem& lens, const MirrorBores& bores) {
    LensOutline out;
    const int n = static_cast<int>(lens.surfaces.size());
    const std::vector<RigidMotion> placed = surfacePlacements(lens);
    for (int i = 0; i < n; ++i) {
        const Surface& s = lens.surfaces[i];
        out.maxRadius = std::max(out.maxRadius, s.apertureRadius);
        if (s.obscurationRadius > 0 && !s.mirror) out.obscurations.push_back({s.z - sag(s, s.obscurationRadius), s.obscurationRadius});
        // A stop on a flat surface between two airs is a diaphragm only: the blades show it.
        if (s.isStop && s.vertexCurvature() == 0 && !s.mirror && s.indexAfter == lens.indexBefore(i)) continue;
        for (auto& piece : arcs(s, placed[i], bores.at(i))) (s.mirror ? out.mirrors : out.lines).push_back(std::move(piece));
        if (s.indexAfter != 1.0 && i + 1 < n)
            addElement({s, placed[i]}, {lens.surfaces[i + 1], placed[i + 1]}, std::max(bores.at(i), bores.at(i + 1)), out);
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
