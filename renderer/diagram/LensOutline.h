#pragma once
// The lens cross-section in the (z, y) plane, in lens millimetres: each surface's true arc up to
// its clear aperture, the glass between surfaces, the element edges, and the aperture stop, each
// drawn where the lens's motions place it (LensLayout.h).
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct MirrorBores;
struct LensLayout;

struct ZY {
    double z = 0, y = 0;  // mm, lens convention (+z toward the scene)
};

// Glass between two surfaces, up to the larger of their clear apertures (the element's edge).
// Both profiles are sampled at the same heights, bottom to top, so the glass is the strip between
// them; a surface smaller than the edge continues flat from its rim, as lens drawings show it. A
// Mangin mirror with a bore is two strips, above and below the hole.
struct GlassElement {
    std::vector<ZY> front, rear;
    double index = 1;
};

// A line drawn across the axis in a surface's vertex plane (or its obscuration's), placed where the
// surface lies.
struct Bar {
    ZY from, to;
};

// The two blades, above the axis and below, each from the opening (at the chosen f-number) out to
// where the blades end in the drawing.
struct StopBlades {
    Bar upper, lower;
};

// A central obscuration on a surface that is not a mirror (a reflex lens's secondary mirror mount),
// drawn as a bar across the axis, from +radius to -radius. An obscuration on a mirror is a hole in
// it, drawn as its bore.
using Obscuration = Bar;

struct LensOutline {
    std::vector<GlassElement> glass;
    std::vector<std::vector<ZY>> lines;    // arcs, flat steps and edges
    std::vector<std::vector<ZY>> mirrors;  // reflecting surfaces' arcs
    std::vector<Obscuration> obscurations;
    StopBlades stop;
    double maxRadius = 0;                // largest clear aperture, stop blades included
    std::vector<ZY> points() const;      // every point drawn: what a view of the whole lens must hold
};

// The surface's z at height y; beyond its clear aperture it continues flat from the rim.
double profileZ(const Surface& s, double y);

// The heights a surface's clear aperture spans in the drawn (meridional) section: -r to r about the
// vertex, or a shaped aperture's own span (an off-axis mirror's segment, REY about ADY).
struct Section {
    double low = 0, high = 0;
    bool holds(double y) const { return y >= low && y <= high; }
};
Section drawnSection(const Surface& s);

// `lens` has its stop opened to the chosen f-number; `layout` is layOutLens(lens). Where `bores` gives
// a mirror's element a hole, its glass, arcs and mirror are drawn from the hole's wall outward
// (MirrorSolids.h).
LensOutline buildLensOutline(const LensSystem& lens, const LensLayout& layout, const MirrorBores& bores);
LensOutline buildLensOutline(const LensSystem& lens);

}  // namespace lenslab
