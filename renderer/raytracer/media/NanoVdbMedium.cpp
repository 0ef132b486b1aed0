#include "media/NanoVdbMedium.h"

#include <algorithm>

namespace lenslab {

namespace {

Transform indexToMediumOf(const NanoVdbGrid& g) {
    Matrix44 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m.m[r][c] = g.indexToWorld[r][c];
    return makeTransform(m);
}

Vec3f indexMinOf(const NanoVdbGrid& g) { return {float(g.activeMin[0]), float(g.activeMin[1]), float(g.activeMin[2])}; }

// Voxel i spans index space [i, i + 1) in NanoVDB's bounding boxes.
Vec3f indexExtentOf(const NanoVdbGrid& g) {
    const auto size = [&](int a) { return float(double(g.activeMax[a]) - g.activeMin[a] + 1); };
    return {size(0), size(1), size(2)};
}

Transform boxToWorldOf(const NanoVdbGrid& g, const Transform& mediumToWorld) {
    const Vec3f lo = indexMinOf(g), e = indexExtentOf(g);
    return mediumToWorld * indexToMediumOf(g) * translate(lo.x, lo.y, lo.z) * scale(e.x, e.y, e.z);
}

}  // namespace

NanoVdbMedium::NanoVdbMedium(NanoVdbGrid density, Vec3f sigmaA, Vec3f sigmaS, const Transform& mediumToWorld,
                             HenyeyGreenstein phase)
    : TrackedBoxMedium(boxToWorldOf(density, mediumToWorld), std::max(0.0f, density.largest) * maxComponent(sigmaA + sigmaS),
                       phase),
      grid_(std::move(density)), sigmaA_(sigmaA), sigmaS_(sigmaS), indexToMedium_(indexToMediumOf(grid_)),
      indexMin_(indexMinOf(grid_)), indexExtent_(indexExtentOf(grid_)) {}

float NanoVdbMedium::densityAtIndex(Vec3f p) const { return std::max(0.0f, grid_.interpolate(p.x, p.y, p.z)); }

float NanoVdbMedium::density(Vec3f p) const { return densityAtIndex(transformPoint(inverse(indexToMedium_), p)); }

void NanoVdbMedium::bounds(Vec3f& lo, Vec3f& hi) const {
    lo = {INFINITY, INFINITY, INFINITY};
    hi = -lo;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3f c = indexMin_ + Vec3f{float(corner & 1), float((corner >> 1) & 1), float(corner >> 2)} * indexExtent_;
        const Vec3f q = transformPoint(indexToMedium_, c);
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
    }
}

void NanoVdbMedium::coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const {
    const float d = densityAtIndex(indexMin_ + pBox * indexExtent_);
    sigmaA = d * sigmaA_;
    sigmaS = d * sigmaS_;
}

}  // namespace lenslab
