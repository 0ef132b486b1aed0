#pragma once
// The density's integral along a ray by the midpoint rule: the reference for tracking tests.
#include "core/Vec3f.h"

namespace lenslab::test {

// The integral of density(p) over p = o + t d, t in [0, length], in `steps` midpoint steps,
// counting only points inside the box lo <= p <= hi.
template <class Density>
double midpointDepth(Vec3f o, Vec3f d, float length, int steps, Vec3f lo, Vec3f hi, Density density) {
    double depth = 0;
    for (int i = 0; i < steps; ++i) {
        const Vec3f p = o + (length * (i + 0.5f) / steps) * d;
        if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z) depth += density(p);
    }
    return depth * length / steps;
}

}  // namespace lenslab::test
