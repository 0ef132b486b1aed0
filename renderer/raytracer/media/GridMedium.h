#pragma once
// A medium whose density is given at the cell centres of an nx x ny x nz grid over a box,
// interpolated trilinearly and zero outside, times sigma_a and sigma_s (pbrt-v3's heterogeneous,
// pbrt-v4's uniformgrid). Tracked against a majorant grid of up to 64 cells per axis, each bounding
// the densities that interpolation reaches in it.
#include <vector>

#include "media/TrackedBoxMedium.h"

namespace lenslab {

struct DensityGrid {
    int nx = 1, ny = 1, nz = 1;
    std::vector<float> density;  // per cell, x fastest: (z * ny + y) * nx + x; never negative
};

class GridMedium final : public TrackedBoxMedium {
public:
    // boxToWorld maps the unit cube onto the grid's box in the world.
    GridMedium(DensityGrid grid, Vec3f sigmaA, Vec3f sigmaS, const Transform& boxToWorld, HenyeyGreenstein phase);
    // The density at pBox in the unit cube's coordinates.
    float density(Vec3f pBox) const;

private:
    void coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const override;

    DensityGrid grid_;
    Vec3f sigmaA_, sigmaS_;
};

// The majorants of sigma_t = density * sigma_t for the grid's densities: a value at cell centre
// (i + 1/2) / n reaches (i - 1/2) / n to (i + 3/2) / n by interpolation.
MajorantGrid densityMajorants(const DensityGrid& grid, float sigmaT);

}  // namespace lenslab
