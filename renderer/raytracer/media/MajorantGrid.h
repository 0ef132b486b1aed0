#pragma once
// Upper bounds of sigma_t (every channel) over the cells of a coarse grid on the unit cube, and the
// walk of a ray through its cells (a 3D DDA): delta and ratio tracking then draw their tentative
// collisions at each cell's own rate, so empty and thin parts of a volume cost few lookups.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Vec3f.h"

namespace lenslab {

struct MajorantGrid {
    int nx = 1, ny = 1, nz = 1;
    std::vector<float> values;  // per cell, x fastest: (z * ny + y) * nx + x

    static MajorantGrid uniform(float majorant) { return {1, 1, 1, {majorant}}; }
    // Zeros over a volume of nx x ny x nz samples: one cell per sample, up to 64 per axis (pbrt-v4's
    // nanovdb resolution; finer cells cost more steps of the walk than they save lookups).
    static MajorantGrid forSamples(int nx, int ny, int nz) {
        const auto cells = [](int n) { return std::clamp(n, 1, 64); };
        MajorantGrid g{cells(nx), cells(ny), cells(nz), {}};
        g.values.assign(std::size_t(g.nx) * g.ny * g.nz, 0.0f);
        return g;
    }
    float at(int x, int y, int z) const { return values[(std::size_t(z) * ny + y) * nx + x]; }
    float& at(int x, int y, int z) { return values[(std::size_t(z) * ny + y) * nx + x]; }
};

// Raises to at least v every cell that meets the box lo..hi of the unit cube (a sample's reach by
// interpolation; it may extend past the cube). Cells touching the box at a face count too, so
// rounding never leaves out a cell the box reaches.
inline void raiseMajorants(MajorantGrid& g, const double lo[3], const double hi[3], float v) {
    const int res[3] = {g.nx, g.ny, g.nz};
    int from[3], to[3];
    for (int a = 0; a < 3; ++a) {
        const double first = std::floor(lo[a] * res[a]), last = std::floor(hi[a] * res[a]);
        if (last < 0 || first >= res[a]) return;
        from[a] = int(std::max(0.0, first));
        to[a] = int(std::min(double(res[a] - 1), last));
    }
    for (int z = from[2]; z <= to[2]; ++z)
        for (int y = from[1]; y <= to[1]; ++y)
            for (int x = from[0]; x <= to[0]; ++x) g.at(x, y, z) = std::max(g.at(x, y, z), v);
}

inline void scaleMajorants(MajorantGrid& g, float factor) {
    for (float& v : g.values) v *= factor;
}

// Calls visit(tStart, tEnd, majorant) for the cells the ray o + t d (unit-cube coordinates) crosses
// between t0 and t1 (both inside the cube), in order, until visit returns false.
template <class Visit>
void walkMajorants(const MajorantGrid& g, Vec3f o, Vec3f d, float t0, float t1, Visit visit) {
    const int res[3] = {g.nx, g.ny, g.nz};
    int cell[3], step[3];
    float tNext[3], tDelta[3];
    for (int a = 0; a < 3; ++a) {
        const float p = (o[a] + t0 * d[a]) * res[a];
        cell[a] = std::clamp(int(std::floor(p)), 0, res[a] - 1);
        if (d[a] == 0) {
            step[a] = 0;
            tNext[a] = tDelta[a] = INFINITY;
            continue;
        }
        step[a] = d[a] > 0 ? 1 : -1;
        tDelta[a] = 1 / (std::abs(d[a]) * res[a]);
        const float boundary = float(cell[a] + (d[a] > 0 ? 1 : 0)) / res[a];
        tNext[a] = std::max(t0, (boundary - o[a]) / d[a]);
    }
    float t = t0;
    for (;;) {
        const int axis = tNext[0] < tNext[1] ? (tNext[0] < tNext[2] ? 0 : 2) : (tNext[1] < tNext[2] ? 1 : 2);
        const float tEnd = std::min(t1, tNext[axis]);
        if (tEnd > t && !visit(t, tEnd, g.at(cell[0], cell[1], cell[2]))) return;
        if (tEnd >= t1) return;
        t = tEnd;
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= res[axis]) return;
        tNext[axis] += tDelta[axis];
    }
}

}  // namespace lenslab
