#include "media/GridMedium.h"

#include <cmath>

namespace lenslab {

MajorantGrid densityMajorants(const DensityGrid& grid, float sigmaT) {
    MajorantGrid m = MajorantGrid::forSamples(grid.nx, grid.ny, grid.nz);
    const int res[3] = {grid.nx, grid.ny, grid.nz};
    std::size_t i = 0;
    for (int z = 0; z < grid.nz; ++z)
        for (int y = 0; y < grid.ny; ++y)
            for (int x = 0; x < grid.nx; ++x, ++i) {
                if (grid.density[i] <= 0) continue;
                const int at[3] = {x, y, z};
                double lo[3], hi[3];
                for (int a = 0; a < 3; ++a) {
                    lo[a] = (at[a] - 0.5) / res[a];
                    hi[a] = (at[a] + 1.5) / res[a];
                }
                raiseMajorants(m, lo, hi, grid.density[i]);
            }
    scaleMajorants(m, sigmaT);
    return m;
}

GridMedium::GridMedium(DensityGrid grid, Vec3f sigmaA, Vec3f sigmaS, const Transform& boxToWorld, HenyeyGreenstein phase)
    : TrackedBoxMedium(boxToWorld, densityMajorants(grid, maxComponent(sigmaA + sigmaS)), phase), grid_(std::move(grid)),
      sigmaA_(sigmaA), sigmaS_(sigmaS) {}

float GridMedium::density(Vec3f p) const {
    const float x = p.x * grid_.nx - 0.5f, y = p.y * grid_.ny - 0.5f, z = p.z * grid_.nz - 0.5f;
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    const float fx = x - ix, fy = y - iy, fz = z - iz;
    const auto at = [&](int cx, int cy, int cz) {
        if (cx < 0 || cy < 0 || cz < 0 || cx >= grid_.nx || cy >= grid_.ny || cz >= grid_.nz) return 0.0f;
        return grid_.density[(std::size_t(cz) * grid_.ny + cy) * grid_.nx + cx];
    };
    const auto lerp = [](float f, float a, float b) { return a + f * (b - a); };
    const auto plane = [&](int cz) {
        return lerp(fy, lerp(fx, at(ix, iy, cz), at(ix + 1, iy, cz)), lerp(fx, at(ix, iy + 1, cz), at(ix + 1, iy + 1, cz)));
    };
    return lerp(fz, plane(iz), plane(iz + 1));
}

void GridMedium::coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const {
    const float d = density(pBox);
    sigmaA = d * sigmaA_;
    sigmaS = d * sigmaS_;
}

}  // namespace lenslab
