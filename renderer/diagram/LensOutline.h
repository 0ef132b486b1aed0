#pragma once
// The lens cross-section in the (z, y) plane, in lens millimetres: each surface's true arc up to
// its clear aperture, the glass between surfaces, the element edges, and the aperture stop.
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct MirrorBores;

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

struct StopBlades {
    double z = 0;
    double openingRadius = 0;  // at the chosen f-number
    double outerRadius = 0;    // where the blades end in the drawing
};

// A central obscuration on a surface that is not a mirror (a reflex lens's secondary mirror mount),
// drawn as a bar across the axis. An obscuration on a mirror is a hole in it, drawn as its bore.
struct Obscuration {
    double z = 0;
    double radius = 0;
};

struct LensOutline {
    std::vector<GlassElement> glass;
    std::vector<std::vector<ZY>> lines;    // arcs, flat steps and edges
    std::vector<std::vector<ZY>> mirrors;  // reflecting surfaces' arcs
    std::vector<Obscuration> obscurations;
    StopBlades stop;
    double maxRadius = 0;                // largest clear aperture, stop blades included
};

// The surface's z at height y; beyond its clear aperture it continues flat from the rim.
double profileZ(const Surface& s, double y);

// `lens` has its stop opened to the chosen f-number. Where `bores` gives a mirror's element a hole,
// its glass, arcs and mirror are drawn from the hole's wall outward (MirrorSolids.h).
LensOutline buildLensOutline(const LensSystem& lens, const MirrorBores& bores);
LensOutline buildLensOutline(const LensSystem& lens);

}  // namespace lenslab
