#include "LensOutline.h"

#include <algorithm>
#include <cmath>

#include "LensLayout.h"
#include "MirrorSolids.h"
#include "trace/ExactTrace.h"

namespace lenslab {

double profileZ(const Surface& s, double y) { return s.z - sag(s, std::min(std::abs(y), s.apertureRadius)); }

Section drawnSection(const Surface& s) {
    if (s.clearShape)
        if (const auto span = s.clearShape->meridionalSpan()) return {span->first, span->second};
    return {-s.apertureRadius, s.apertureRadius};
}

namespace {

constexpr int kArcSteps = 64;

// The height ranges a surface or element is drawn over: its whole section, or the pieces outside a bore.
std::vector<std::pair<double, double>> drawnSpans(double bore, Section section) {
    if (!(bore > 0)) return {{section.low, section.high}};
    std::vector<std::pair<double, double>> pieces;
    if (section.low <= -bore) pieces.push_back({section.low, std::min(section.high, -bore)});
    if (section.high >= bore) pieces.push_back({std::max(section.low, bore), section.high});
    return pieces;
}

// Heights from low to high, with the rims of both surfaces exactly on the list where they fall inside.
std::vector<double> sampleHeights(double low, double high, Section a, Section b) {
    std::vector<double> h;
    for (int i = 0; i <= kArcSteps; ++i) h.push_back(low + (high - low) * i / kArcSteps);
    for (double rim : {a.high, b.high, a.low, b.low})
        if (rim > low && rim < high) h.push_back(rim);
    std::sort(h.begin(), h.end());
    h.erase(std::unique(h.begin(), h.end()), h.end());
    return h;
}

// A point of a surface's profile (height y in its meridional plane) where the drawing shows it.
ZY placedPoint(const RigidMotion& placement, const Surface& s, double y) {
    return LensLayout::place(placement, {0, y, profileZ(s, y)});
}

// The bar at z of a surface's own frame from height y0 to y1.
Bar placedBar(const RigidMotion& placement, double z, double y0, double y1) {
    return {LensLayout::place(placement, {0, y0, z}), LensLayout::place(placement, {0, y1, z})};
}

std::vector<std::vector<ZY>> arcs(const Surface& s, const RigidMotion& placement, double bore) {
    std::vector<std::vector<ZY>> pieces;
    const Section section = drawnSection(s);
    for (const auto& [low, high] : drawnSpans(bore, section)) {
        pieces.emplace_back();
        for (double y : sampleHeights(low, high, section, section))
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
    const Section a = drawnSection(front.surface), b = drawnSection(rear.surface);
    const Section edge{std::min(a.low, b.low), std::max(a.high, b.high)};
    for (const auto& [low, high] : drawnSpans(bore, edge)) {
        GlassElement g;
        g.index = front.surface.indexAfter;
        for (double y : sampleHeights(low, high, a, b)) {
            g.front.push_back(front.at(y));
            g.rear.push_back(rear.at(y));
        }
        out.glass.push_back(std::move(g));
    }
    for (const PlacedSurface* s : {&front, &rear}) {
        const Section own = drawnSection(s->surface);
        // The flat step from the rim out to the element's edge (profileZ holds the rim's z beyond it).
        if (own.high < edge.high) out.lines.push_back({s->at(own.high), s->at(edge.high)});
        if (own.low > edge.low) out.lines.push_back({s->at(own.low), s->at(edge.low)});
    }
    // The element's edges, and the bore's walls.
    for (double y : {edge.high, edge.low}) out.lines.push_back({front.at(y), rear.at(y)});
    if (bore > 0)
        for (double y : {bore, -bore})
            if (edge.holds(y)) out.lines.push_back({front.at(y), rear.at(y)});
}

}  // namespace

std::vector<ZY> LensOutline::points() const {
    std::vector<ZY> all;
    for (const GlassElement& g : glass) {
        all.insert(all.end(), g.front.begin(), g.front.end());
        all.insert(all.end(), g.rear.begin(), g.rear.end());
    }
    for (const auto* group : {&lines, &mirrors})
        for (const auto& line : *group) all.insert(all.end(), line.begin(), line.end());
    for (const Bar& b : obscurations) all.insert(all.end(), {b.from, b.to});
    for (const Bar& b : {stop.upper, stop.lower}) all.insert(all.end(), {b.from, b.to});
    return all;
}

LensOutline buildLensOutline(const LensSystem& lens) { return buildLensOutline(lens, layOutLens(lens), MirrorBores{}); }

LensOutline buildLensOutline(const LensSystem& lens, const LensLayout& layout, const MirrorBores& bores) {
    LensOutline out;
    const int n = static_cast<int>(lens.surfaces.size());
    const std::vector<RigidMotion>& placed = layout.own;
    for (int i = 0; i < n; ++i) {
        const Surface& s = lens.surfaces[i];
        // A decentred lens's dummy plane only places the coordinates after it: nothing is there.
        if (isDummy(lens, i)) continue;
        out.maxRadius = std::max(out.maxRadius, s.apertureRadius);
        if (s.obscurationRadius > 0 && !s.mirror)
            out.obscurations.push_back(placedBar(placed[i], s.z - sag(s, s.obscurationRadius), s.obscurationRadius, -s.obscurationRadius));
        // A stop on a flat surface between two airs is a diaphragm only: the blades show it.
        if (s.isStop && s.vertexCurvature() == 0 && !s.mirror && s.indexAfter == lens.indexBefore(i)) continue;
        for (auto& piece : arcs(s, placed[i], bores.at(i))) (s.mirror ? out.mirrors : out.lines).push_back(std::move(piece));
        if (s.indexAfter != 1.0 && i + 1 < n)
            addElement({s, placed[i]}, {lens.surfaces[i + 1], placed[i + 1]}, std::max(bores.at(i), bores.at(i + 1)), out);
    }
    // The blades reach past the neighbouring elements so the stop reads as a diaphragm. A neighbour
    // placed elsewhere (a decentred or folded system's) is not beside it: with none beside it the
    // blades reach half the opening beyond it.
    const Surface& stop = lens.stop();
    double around = 0;
    for (int i : {lens.stopIndex - 1, lens.stopIndex + 1})
        if (i >= 0 && i < n && placed[i] == placed[lens.stopIndex]) around = std::max(around, lens.surfaces[i].apertureRadius);
    const double outer = around > 0 ? 1.12 * std::max(around, stop.apertureRadius) : 1.5 * stop.apertureRadius;
    out.stop = {placedBar(placed[lens.stopIndex], stop.z, stop.apertureRadius, outer),
                placedBar(placed[lens.stopIndex], stop.z, -stop.apertureRadius, -outer)};
    out.maxRadius = std::max(out.maxRadius, outer);
    return out;
}

}  // namespace lenslab
