#pragma once
// A medium whose coefficients are values on an nx x ny x nz grid of cell centres over a box,
// interpolated trilinearly (pbrt-v3's heterogeneous, pbrt-v4's uniformgrid). The majorant is the
// largest coefficient anywhere.
#include <vector>

#include "media/TrackedBoxMedium.h"

namespace lenslab {

struct MediumGrid {
    int nx = 1, ny = 1, nz = 1;
    std::vector<Vec3f> sigmaA, sigmaS;  // per cell, x fastest: (z * ny + y) * nx + x
};

class GridMedium final : public TrackedBoxMedium {
public:
    // boxToWorld maps the unit cube onto the grid's box in the world.
    GridMedium(MediumGrid grid, const Transform& boxToWorld, HenyeyGreenstein phase);

private:
    void coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const override;

    MediumGrid grid_;
};

}  // namespace lenslab
