#include "media/NanoVdbMedium.h"

#include <algorithm>
#include <cmath>

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

// The largest density each cell of a grid over the index box can see: every stored value (voxel,
// tile, background) raised over the cells its voxels reach by interpolation, one voxel beyond each
// side.
class DensityMajorants {
public:
    explicit DensityMajorants(const NanoVdbGrid& g)
        : g_(g), lo_(indexMinOf(g)), extent_(indexExtentOf(g)),
          m_(MajorantGrid::forSamples(int(extent_.x), int(extent_.y), int(extent_.z))) {
        for (float& v : m_.values) v = std::max(0.0f, g.background);
    }

    MajorantGrid scaled(float sigmaT) {
        for (const auto& tile : g_.root) {
            const std::array<int, 3> origin = rootOrigin(tile.key);
            if (tile.upper < 0)
                raise(origin, 4096, tile.value);
            else
                upper(std::size_t(tile.upper), origin);
        }
        scaleMajorants(m_, sigmaT);
        return std::move(m_);
    }

private:
    static std::array<int, 3> rootOrigin(uint64_t key) {
        constexpr uint64_t k21 = (1u << 21) - 1;
        return {int32_t(uint32_t((key >> 42) & k21) << 12), int32_t(uint32_t((key >> 21) & k21) << 12),
                int32_t(uint32_t(key & k21) << 12)};
    }
    // The origin of slot n of a node with 2^log2 slots per axis, each `size` voxels wide.
    static std::array<int, 3> slotOrigin(const std::array<int, 3>& node, int n, int log2, int size) {
        const int mask = (1 << log2) - 1;
        return {node[0] + ((n >> (2 * log2)) & mask) * size, node[1] + ((n >> log2) & mask) * size, node[2] + (n & mask) * size};
    }
    void upper(std::size_t u, const std::array<int, 3>& origin) {
        for (int n = 0; n < kNanoVdbUpperSlots; ++n) {
            const std::size_t slot = u * kNanoVdbUpperSlots + n;
            if (g_.upperChild[slot] < 0)
                raise(slotOrigin(origin, n, 5, 128), 128, g_.upperValue[slot]);
            else
                lower(std::size_t(g_.upperChild[slot]), slotOrigin(origin, n, 5, 128));
        }
    }
    void lower(std::size_t l, const std::array<int, 3>& origin) {
        for (int n = 0; n < kNanoVdbLowerSlots; ++n) {
            const std::size_t slot = l * kNanoVdbLowerSlots + n;
            if (g_.lowerChild[slot] < 0) {
                raise(slotOrigin(origin, n, 4, 8), 8, g_.lowerValue[slot]);
            } else {
                leaf(std::size_t(g_.lowerChild[slot]), slotOrigin(origin, n, 4, 8));
            }
        }
    }
    // Each voxel on its own: the cells of a leaf's empty and thin parts keep low majorants.
    void leaf(std::size_t f, const std::array<int, 3>& origin) {
        const float* v = &g_.leafValues[f * kNanoVdbLeafVoxels];
        for (int n = 0; n < kNanoVdbLeafVoxels; ++n) raise(slotOrigin(origin, n, 3, 1), 1, v[n]);
    }
    // Voxels origin .. origin + size - 1 hold values up to v: index space from one voxel below to
    // one above sees it.
    void raise(const std::array<int, 3>& origin, int size, float v) {
        if (v <= 0) return;
        double lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = (double(origin[a]) - 1 - lo_[a]) / extent_[a];
            hi[a] = (double(origin[a]) + size - lo_[a]) / extent_[a];
        }
        raiseMajorants(m_, lo, hi, v);
    }

    const NanoVdbGrid& g_;
    Vec3f lo_, extent_;
    MajorantGrid m_;
};

Transform boxToWorldOf(const NanoVdbGrid& g, const Transform& mediumToWorld) {
    const Vec3f lo = indexMinOf(g), e = indexExtentOf(g);
    return mediumToWorld * indexToMediumOf(g) * translate(lo.x, lo.y, lo.z) * scale(e.x, e.y, e.z);
}

}  // namespace

MajorantGrid nanoVdbMajorants(const NanoVdbGrid& g, float sigmaT) { return DensityMajorants(g).scaled(sigmaT); }

NanoVdbMedium::NanoVdbMedium(NanoVdbGrid density, Vec3f sigmaA, Vec3f sigmaS, const Transform& mediumToWorld,
                             HenyeyGreenstein phase)
    : TrackedBoxMedium(boxToWorldOf(density, mediumToWorld), nanoVdbMajorants(density, maxComponent(sigmaA + sigmaS)),
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
