#pragma once
// An independent paraxial y-nu trace, written for the tests from the textbook recurrences
// (refraction n'u' = nu - y (n' - n) c, transfer y' = y + t u'), in the designer's frame where
// light travels along +s = -z. It shares no code with optics/ beyond reading the lens table.
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab::test {

struct YNuSurface {
    double s = 0;          // position along +s (= -z)
    double curvature = 0;  // at the vertex (all a paraxial ray sees), in the +s frame
    double nBefore = 1, nAfter = 1;
};

// Surfaces [begin, end) as met by light going toward the film (forward) or toward the scene
// (reversed: order, curvature sign and s all flip so light still travels along +s).
inline std::vector<YNuSurface> ynuSystem(const LensSystem& lens, int begin, int end, bool reversed) {
    std::vector<YNuSurface> out;
    for (int i = begin; i < end; ++i) {
        const Surface& x = lens.surfaces[i];
        const double nScene = i == 0 ? 1.0 : lens.surfaces[i - 1].indexAfter;
        if (!reversed) out.push_back({-x.z, x.vertexCurvature(), nScene, x.indexAfter});
        else out.insert(out.begin(), {x.z, -x.vertexCurvature(), x.indexAfter, nScene});
    }
    return out;
}

struct YNu {
    double y = 0, u = 0, s = 0;  // height, slope and position after the last surface (air)
};

// Starts at position s0 with height y and slope u in air.
inline YNu traceYNu(const std::vector<YNuSurface>& sys, double s0, double y, double u) {
    double s = s0, n = 1.0;
    for (const YNuSurface& k : sys) {
        y += (k.s - s) * u;
        s = k.s;
        const double nu = n * u - y * (k.nAfter - k.nBefore) * k.curvature;
        n = k.nAfter;
        u = nu / n;
    }
    return {y, u, s};
}

// Where the ray meets the axis, measured along +s.
inline double axisCrossing(const YNu& r) { return r.s - r.y / r.u; }

}  // namespace lenslab::test
