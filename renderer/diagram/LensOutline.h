#pragma once
// The lens cross-section in the (z, y) plane, in lens millimetres: each surface's true arc up to
// its clear aperture, the glass between surfaces, the element edges, and the aperture stop.
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct ZY {
    double z = 0, y = 0;  // mm, lens convention (+z toward the scene)
};

// Glass between two surfaces, up to the larger of their clear apertures (the element's edge).
// Both profiles are sampled at the same heights, bottom to top, so the glass is the strip between
// them; a surface smaller than the edge continues flat from its rim, as lens drawings show it.
struct GlassElement {
    std::vector<ZY> front, rear;
    double index = 1;
};

struct StopBlades {
    double z = 0;
    double openingRadius = 0;  // at the chosen f-number
    double outerRadius = 0;    // where the blades end in the drawing
};

// A central obscuration (a reflex lens's secondary mirror mount) drawn as a bar across the axis.
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

// `lens` has its stop opened to the chosen f-number.
LensOutline buildLensOutline(const LensSystem& lens);

}  // namespace lenslab
