#include "media/GridMedium.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

// Trilinear weights never exceed their largest corner.
float largestCoefficient(const MediumGrid& grid) {
    float m = 0;
    for (std::size_t i = 0; i < grid.sigmaA.size(); ++i) m = std::max(m, maxComponent(grid.sigmaA[i] + grid.sigmaS[i]));
    return m;
}

}  // namespace

GridMedium::GridMedium(MediumGrid grid, const Transform& boxToWorld, HenyeyGreenstein phase)
    : TrackedBoxMedium(boxToWorld, MajorantGrid::uniform(largestCoefficient(grid)), phase), grid_(std::move(grid)) {}

void GridMedium::coefficients(Vec3f p, Vec3f& sigmaA, Vec3f& sigmaS) const {
    const float x = p.x * grid_.nx - 0.5f, y = p.y * grid_.ny - 0.5f, z = p.z * grid_.nz - 0.5f;
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    const float fx = x - ix, fy = y - iy, fz = z - iz;
    sigmaA = sigmaS = {};
    for (int corner = 0; corner < 8; ++corner) {
        const int cx = ix + (corner & 1), cy = iy + ((corner >> 1) & 1), cz = iz + (corner >> 2);
        if (cx < 0 || cy < 0 || cz < 0 || cx >= grid_.nx || cy >= grid_.ny || cz >= grid_.nz) continue;
        const float w = ((corner & 1) ? fx : 1 - fx) * (((corner >> 1) & 1) ? fy : 1 - fy) * ((corner >> 2) ? fz : 1 - fz);
        const std::size_t i = (std::size_t(cz) * grid_.ny + cy) * grid_.nx + cx;
        sigmaA += w * grid_.sigmaA[i];
        sigmaS += w * grid_.sigmaS[i];
    }
}

}  // namespace lenslab
