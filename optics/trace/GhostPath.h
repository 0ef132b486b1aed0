#pragma once
// Ghosts: light reflected at one surface on its way to the film, back to an earlier surface, and
// reflected there toward the film again. Such a path is itself a sequential lens, the lens unfolded:
// the surfaces up to the first reflection, that surface as a mirror, the surfaces between met again
// in reverse, the second as a mirror, then on to the film. The exact trace (mirrors, light going
// back toward the scene) and the ray-transfer matrices then serve ghosts as they serve the lens.
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct GhostPath {
    int first = 0;   // the surface reflecting the light back toward the scene (index into the lens)
    int second = 0;  // the earlier surface sending it on toward the film (second < first)
};

// Surfaces that reflect part of the light: refracting surfaces (not mirrors, not the stop) between
// different media or carrying a coating. A lens with N of them has N (N - 1) / 2 ghosts.
std::vector<int> reflectingSurfaces(const LensSystem& lens);
std::vector<GhostPath> ghostPaths(const LensSystem& lens);

// One surface of an unfolded ghost: which surface of the lens, met from which side (fromScene: the
// side toward the scene in the lens's sequence), and whether the light reflects there (the two
// ghost reflections, and the lens's own mirrors) or passes.
struct GhostStep {
    int surface = 0;
    bool fromScene = true;
    bool reflects = false;
};

struct UnfoldedGhost {
    LensSystem lens;               // the path as a lens; its stopIndex the first time it meets the stop
    std::vector<GhostStep> steps;  // one per surface of `lens`
};

// Throws OpticsError unless path.second < path.first name surfaces of the lens.
UnfoldedGhost unfoldGhost(const LensSystem& lens, GhostPath path);

}  // namespace lenslab
