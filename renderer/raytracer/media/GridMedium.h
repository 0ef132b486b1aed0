#pragma once
// A medium whose coefficients vary over a box: values on an nx x ny x nz grid of cell centres,
// interpolated trilinearly and zero outside the box (pbrt's heterogeneous, uniformgrid and rgb
// media). Distances by delta tracking and transmittance by ratio tracking against one majorant,
// the largest coefficient anywhere (trilinear weights never exceed their largest corner).
#include <vector>

#include "media/ParticipatingMedium.h"

namespace lenslab {

struct MediumGrid {
    int nx = 1, ny = 1, nz = 1;
    std::vector<Vec3f> sigmaA, sigmaS;  // per cell, x fastest: (z * ny + y) * nx + x
};

class GridMedium final : public ParticipatingMedium {
public:
    // boxToWorld maps the unit cube onto the grid's box in the world.
    GridMedium(MediumGrid grid, const Transform& boxToWorld, HenyeyGreenstein phase);
    MediumEvent sample(Vec3f o, Vec3f d, float tMax, int hero, Pcg32& rng) const override;
    Vec3f transmittance(Vec3f o, Vec3f d, float tMax, Pcg32& rng) const override;

private:
    // Where the ray o + t d (world) runs inside the box, clipped to [0, tMax]; false if nowhere.
    // oBox, dBox: the ray in the box's unit-cube coordinates, with the same t.
    bool clip(Vec3f o, Vec3f d, float tMax, Vec3f& oBox, Vec3f& dBox, float& t0, float& t1) const;
    void lookup(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const;

    MediumGrid grid_;
    Transform worldToBox_;
    float majorant_ = 0;
};

}  // namespace lenslab
