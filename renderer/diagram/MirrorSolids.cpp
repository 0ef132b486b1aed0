#include "MirrorSolids.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "LensLayout.h"

namespace lenslab {

namespace {

// A ray's own hit on a surface lies on its profile to rounding: no crossing that close to a
// segment's end counts.
constexpr double kEndClearance = 1e-6;  // mm

struct Crossing {
    double t = 0;  // along the segment, 0 at a, 1 at b
    ZY point;
};

// How far a point (in the surface's own frame) lies off the surface's profile along z, at its height.
double gapToProfile(const Surface& s, ZY p) { return p.z - profileZ(s, std::abs(p.y)); }

ZY along(ZY a, ZY b, double t) { return {a.z + t * (b.z - a.z), a.y + t * (b.y - a.y)}; }

// The first place strictly inside segment a-b where it crosses the profile of `s` at a height |y|
// between rMin and rMax, within the surface's section (a shaped mirror is solid only over its own
// segment). The segment is searched only where its z lies within the profile's.
std::optional<Crossing> firstProfileCrossing(const Surface& s, ZY a, ZY b, double rMin, double rMax) {
    if (!(rMax > rMin)) return std::nullopt;
    const double length = std::hypot(b.z - a.z, b.y - a.y);
    if (!(length > 2 * kEndClearance)) return std::nullopt;
    double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo;
    constexpr int kProfileSamples = 32;
    for (int k = 0; k <= kProfileSamples; ++k) {
        const double z = profileZ(s, rMin + (rMax - rMin) * k / kProfileSamples);
        zLo = std::min(zLo, z);
        zHi = std::max(zHi, z);
    }
    const double margin = 1e-3 * (zHi - zLo) + 1e-6;
    double t0 = 0, t1 = 1;
    if (b.z != a.z) {
        double ta = (zLo - margin - a.z) / (b.z - a.z), tb = (zHi + margin - a.z) / (b.z - a.z);
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    } else if (a.z < zLo - margin || a.z > zHi + margin) {
        return std::nullopt;
    }
    if (!(t1 > t0)) return std::nullopt;
    auto gap = [&](double t) { return gapToProfile(s, along(a, b, t)); };
    constexpr int kSteps = 64;
    double tPrev = t0, gPrev = gap(t0);
    for (int k = 1; k <= kSteps; ++k) {
        const double t = t0 + (t1 - t0) * k / kSteps, g = gap(t);
        if ((gPrev < 0) != (g < 0)) {
            double lo = tPrev, hi = t;
            const bool loNegative = gPrev < 0;
            for (int i = 0; i < 60; ++i) {
                const double mid = 0.5 * (lo + hi);
                ((gap(mid) < 0) == loNegative ? lo : hi) = mid;
            }
            const double root = 0.5 * (lo + hi);
            const ZY p = along(a, b, root);
            const bool clear = root * length > kEndClearance && (1 - root) * length > kEndClearance;
            if (clear && std::abs(p.y) >= rMin && std::abs(p.y) <= rMax && drawnSection(s).holds(p.y)) return Crossing{root, p};
        }
        tPrev = t;
        gPrev = g;
    }
    return std::nullopt;
}

bool hasGlassAfter(const LensSystem& lens, int i) { return lens.surfaces[i].indexAfter != 1.0; }

// A flat between equal media that is no mirror: a stop's diaphragm or a dummy plane, no solid a
// mirror would need a hole for (off-axis telescopes set their stop at a mirror).
bool isDiaphragm(const LensSystem& lens, int i) {
    const Surface& s = lens.surfaces[i];
    return s.vertexCurvature() == 0 && !s.mirror && s.indexAfter == lens.indexBefore(i);
}

// Whether a drawn point lies in the glass between two consecutive surfaces of the element: on the
// film side of one face and the scene side of the other, each face judged in its own frame.
bool insideElementGlass(const LensSystem& lens, const LensLayout& layout, const std::vector<int>& element, ZY p) {
    for (std::size_t k = 0; k + 1 < element.size(); ++k) {
        const int f = element[k], r = element[k + 1];
        const Surface &front = lens.surfaces[f], &rear = lens.surfaces[r];
        if (!hasGlassAfter(lens, f)) continue;
        const ZY inFront = intoSpace(layout.own[f], p), inRear = intoSpace(layout.own[r], p);
        if (std::abs(inFront.y) > std::max(front.apertureRadius, rear.apertureRadius)) continue;
        if (gapToProfile(front, inFront) * gapToProfile(rear, inRear) < 0) return true;
    }
    return false;
}

// Whether surface `other` is set inside the element: part of its arc in the element's glass, or
// crossing the mirror itself.
bool setInside(const LensSystem& lens, const LensLayout& layout, const std::vector<int>& element, int mirror, int other) {
    constexpr int kArcSamples = 32;
    const Surface &m = lens.surfaces[mirror], &o = lens.surfaces[other];
    // The other surface's arc where it is drawn, and in the mirror's frame.
    auto arcPoint = [&](double y) { return LensLayout::place(layout.own[other], {0, y, profileZ(o, y)}); };
    const Section section = drawnSection(o);
    ZY previous = intoSpace(layout.own[mirror], arcPoint(section.low));
    for (int k = 0; k <= kArcSamples; ++k) {
        const ZY drawn = arcPoint(section.low + (section.high - section.low) * k / kArcSamples);
        const ZY p = intoSpace(layout.own[mirror], drawn);
        if (insideElementGlass(lens, layout, element, drawn)) return true;
        if (k > 0 && firstProfileCrossing(m, previous, p, 0, m.apertureRadius)) return true;
        previous = p;
    }
    return false;
}

}  // namespace

std::vector<int> mirrorElement(const LensSystem& lens, int surface) {
    int first = surface, last = surface;
    while (first > 0 && hasGlassAfter(lens, first - 1)) --first;
    while (last + 1 < static_cast<int>(lens.surfaces.size()) && hasGlassAfter(lens, last)) ++last;
    std::vector<int> element;
    for (int i = first; i <= last; ++i) element.push_back(i);
    return element;
}

MirrorBores findMirrorBores(const LensSystem& lens, const LensLayout& layout, const std::vector<std::vector<ZY>>& passingLight) {
    const int n = static_cast<int>(lens.surfaces.size());
    MirrorBores bores;
    bores.radius.assign(n, 0.0);
    for (int i = 0; i < n; ++i) {
        const Surface& mirror = lens.surfaces[i];
        if (!mirror.mirror) continue;
        const std::vector<int> element = mirrorElement(lens, i);
        double bore = mirror.obscurationRadius;
        // Light comes to the mirror travelling this way along its own frame's z; passing light that
        // crosses the element travelling the same way comes from the reflecting side and needs a hole.
        const double arrival = mirror.before.applyToDirection({0, 0, lens.zDirectionAfter(i - 1)})[2];
        // The light on its way to the mirror through the diaphragms just before it is arriving light
        // (a decentred system's stop may lie past the mirror's rim, met by virtual propagation).
        int arriving = element.front();
        while (arriving > 0 && isDiaphragm(lens, arriving - 1)) --arriving;
        for (const auto& path : passingLight) {
            for (std::size_t k = 1; k < path.size(); ++k) {
                // Segment k ends at surface k - 1 (path[0] is the start).
                const int endsAt = static_cast<int>(k) - 1;
                if (endsAt >= arriving && endsAt < element.front()) continue;
                const ZY from = intoSpace(layout.own[i], path[k - 1]), to = intoSpace(layout.own[i], path[k]);
                if ((to.z - from.z) * arrival <= 0) continue;
                for (int j : element) {
                    const Surface& s = lens.surfaces[j];
                    const ZY a = intoSpace(layout.own[j], path[k - 1]), b = intoSpace(layout.own[j], path[k]);
                    if (const auto c = firstProfileCrossing(s, a, b, bore, s.apertureRadius)) bore = std::max(bore, std::abs(c->point.y));
                }
            }
        }
        for (int j = 0; j < n; ++j)
            if (std::find(element.begin(), element.end(), j) == element.end() && !isDiaphragm(lens, j) &&
                setInside(lens, layout, element, i, j))
                bore = std::max(bore, lens.surfaces[j].apertureRadius);
        bore = std::min(bore, mirror.apertureRadius);
        for (int j : element) bores.radius[j] = std::max(bores.radius[j], bore);
    }
    return bores;
}

std::optional<ZY> firstSolidMirrorCrossing(const LensSystem& lens, const LensLayout& layout, const MirrorBores& bores, ZY a, ZY b) {
    // Where along a-b is the same in every frame: the first crossing is found mirror by mirror, each
    // in its own frame, and brought back to the drawing.
    std::optional<Crossing> first;
    for (int i = 0; i < static_cast<int>(lens.surfaces.size()); ++i) {
        const Surface& s = lens.surfaces[i];
        if (!s.mirror) continue;
        auto c = firstProfileCrossing(s, intoSpace(layout.own[i], a), intoSpace(layout.own[i], b), bores.at(i), s.apertureRadius);
        if (!c || (first && c->t >= first->t)) continue;
        c->point = LensLayout::place(layout.own[i], {0, c->point.y, c->point.z});
        first = c;
    }
    if (!first) return std::nullopt;
    return first->point;
}

}  // namespace lenslab
