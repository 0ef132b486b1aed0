#include "firstorder/FilmPlanePupilBounds.h"

#include <algorithm>
#include <cmath>

#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "trace/RayBatch.h"

namespace lenslab {

namespace {

constexpr int kCells = 64;  // search grid cells across the aiming disc

// The passing points of a grid of cells x cells over the square of half-width `extent` around
// (cx, cy), seen from `from`: their centroid, their farthest distance from it (one cell's diagonal
// added, so the circle holds the passing cells whole) and whether any lies near the square's edge.
struct NodeScan {
    PupilCircle circle;
    bool touchesEdge = false;
};

NodeScan scanNode(const LensSystem& lens, const Vec3& from, double aimZ, double cx, double cy, double extent, int cells,
                  RayBatch& batch) {
    const double cell = 2 * extent / cells;
    const auto point = [&](int k) {
        return Vec3{cx - extent + (k % cells + 0.5) * cell, cy - extent + (k / cells + 0.5) * cell, aimZ};
    };
    batch.resize(std::size_t(cells) * cells);
    for (int k = 0; k < cells * cells; ++k) batch.set(k, {from, normalize(point(k) - from)});
    traceBatch(lens, batch, TraceDirection::FilmToScene);
    NodeScan s;
    double sx = 0, sy = 0;
    int count = 0;
    for (int k = 0; k < cells * cells; ++k) {
        if (batch.blocked[k] != BlockReason::None) continue;
        const Vec3 p = point(k);
        sx += p.x;
        sy += p.y;
        ++count;
        if (std::max(std::fabs(p.x - cx), std::fabs(p.y - cy)) > extent - 1.5 * cell) s.touchesEdge = true;
    }
    if (count == 0) return s;
    s.circle.x = sx / count;
    s.circle.y = sy / count;
    for (int k = 0; k < cells * cells; ++k)
        if (batch.blocked[k] == BlockReason::None) {
            const Vec3 p = point(k);
            s.circle.radius = std::max(s.circle.radius, std::hypot(p.x - s.circle.x, p.y - s.circle.y) + std::sqrt(2.0) * cell);
        }
    return s;
}

// A coarse scan around the axis (widened until nothing passes at its edge), then a fine one over
// the square around the circle it found, so that the circle is a few percent wider than the region.
PupilCircle measureNode(const LensSystem& lens, const Vec3& from, double aimZ, double aimRadius, RayBatch& batch) {
    double extent = 1.5 * aimRadius;
    NodeScan s = scanNode(lens, from, aimZ, 0, 0, extent, kCells, batch);
    for (int grow = 0; grow < 4 && s.touchesEdge; ++grow) {
        extent *= 2;
        s = scanNode(lens, from, aimZ, 0, 0, extent, kCells, batch);
    }
    if (s.circle.radius == 0) s = scanNode(lens, from, aimZ, 0, 0, extent, 4 * kCells, batch);  // a sliver the coarse grid missed
    if (s.circle.radius == 0) return {};
    const NodeScan fine = scanNode(lens, from, aimZ, s.circle.x, s.circle.y, s.circle.radius, kCells, batch);
    return fine.circle.radius > 0 ? fine.circle : s.circle;
}

// The film must stay behind the rear surface everywhere: the rear vertex, or its rim where the
// surface bulges toward the film.
void checkFilmBehindLens(const LensSystem& lens, const FilmPlane& film, double halfU, double halfV) {
    const Surface& rear = lens.surfaces.back();
    const double rimSag = sag(rear, rear.apertureRadius);
    const double limit = lens.rearZ() - std::max(0.0, std::isfinite(rimSag) ? rimSag : 0.0);
    for (const double su : {-1.0, 1.0})
        for (const double sv : {-1.0, 1.0}) {
            const Vec3 corner = film.at(su * halfU, sv * halfV);
            if (!(corner.z < limit))
                throw OpticsError("the tilted film reaches z = " + formatNumber(corner.z) + " mm at its corner, into the lens (its rear surface ends at z = " +
                                  formatNumber(limit) + " mm): tilt less or focus farther");
        }
}

}  // namespace

Vec3 FilmPlane::normal() const {
    const Vec3 n{uAxis.y * vAxis.z - uAxis.z * vAxis.y, uAxis.z * vAxis.x - uAxis.x * vAxis.z,
                 uAxis.x * vAxis.y - uAxis.y * vAxis.x};
    return n.z < 0 ? -n : n;
}

FilmPlanePupilBounds computeFilmPlanePupilBounds(const LensSystem& lens, const FilmPlane& film, double halfU,
                                                 double halfV, double aimZ, double aimRadius, int nodesU, int nodesV) {
    if (!(halfU > 0 && halfV > 0) || nodesU < 2 || nodesV < 2 || !(aimRadius > 0))
        throw OpticsError("film plane pupil bounds need a film of positive size, at least 2 x 2 nodes and an aiming radius");
    checkFilmBehindLens(lens, film, halfU, halfV);
    FilmPlanePupilBounds b{film, aimZ, halfU, halfV, nodesU, nodesV, {}};
    RayBatch batch;
    for (int j = 0; j < nodesV; ++j)
        for (int i = 0; i < nodesU; ++i) {
            const double u = -halfU + 2 * halfU * i / (nodesU - 1), v = -halfV + 2 * halfV * j / (nodesV - 1);
            b.nodes.push_back(measureNode(lens, film.at(u, v), aimZ, aimRadius, batch));
        }
    return b;
}

PupilCircle filmPlanePupilCircle(const FilmPlanePupilBounds& b, double u, double v) {
    // Grid coordinates, clamped to the grid (the nearest node's circle beyond it).
    const double gu = std::clamp((u + b.halfU) / (2 * b.halfU) * (b.nodesU - 1), 0.0, double(b.nodesU - 1));
    const double gv = std::clamp((v + b.halfV) / (2 * b.halfV) * (b.nodesV - 1), 0.0, double(b.nodesV - 1));
    const int i = std::min(int(gu), b.nodesU - 2), j = std::min(int(gv), b.nodesV - 2);
    const double fu = gu - i, fv = gv - j;
    const PupilCircle* corner[4] = {&b.nodes[j * b.nodesU + i], &b.nodes[j * b.nodesU + i + 1],
                                    &b.nodes[(j + 1) * b.nodesU + i], &b.nodes[(j + 1) * b.nodesU + i + 1]};
    const double weight[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
    // The centre from the nodes where rays pass (an empty node has no centre to pull toward).
    PupilCircle c;
    double total = 0;
    for (int k = 0; k < 4; ++k)
        if (corner[k]->radius > 0) {
            c.x += weight[k] * corner[k]->x;
            c.y += weight[k] * corner[k]->y;
            total += weight[k];
        }
    if (total == 0) return c;  // on an empty node, or between empty ones: no ray passes
    c.x /= total;
    c.y /= total;
    for (const PupilCircle* n : corner)
        if (n->radius > 0) c.radius = std::max(c.radius, n->radius + std::hypot(n->x - c.x, n->y - c.y));
    c.radius *= 1 + b.margin;
    return c;
}

}  // namespace lenslab
