#pragma once
// The Henyey-Greenstein phase function: how a medium scatters light by the angle between the
// direction of travel before and after. g in (-1, 1): > 0 forward, < 0 backward, 0 isotropic.
// Sampled exactly (the inverse of its cumulative distribution), so a phase sample's weight is 1.
#include "core/Vec3f.h"

namespace lenslab {

class HenyeyGreenstein {
public:
    explicit HenyeyGreenstein(float g = 0) : g_(g) {}
    float g() const { return g_; }
    // Density per steradian of leaving along wi for light travelling along d (both unit).
    float evaluate(Vec3f d, Vec3f wi) const;
    // A direction drawn with density evaluate(d, .).
    Vec3f sample(Vec3f d, float u1, float u2) const;

private:
    float g_;
};

}  // namespace lenslab
