// The grid media (pbrt-v4's uniformgrid, pbrt-v3's heterogeneous): their majorant grid bounds the
// interpolated density everywhere (a majorant below the density biases delta and ratio tracking)
// and is zero where no sample reaches, and tracking through a grid with empty regions gives the
// transmittance exp(-integral of sigma_t) found by quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "MidpointDepth.h"
#include "media/GridMedium.h"

namespace lenslab {
namespace {

const Vec3f kGridSigmaA{0.4f, 0.7f, 1.0f}, kGridSigmaS{2.0f, 1.0f, 0.5f};
const float kSigmaT = 2.4f;  // the largest channel of sigma_a + sigma_s

// 9 x 6 x 80 samples (the last axis finer than the majorant grid's 64 cells, so cells and samples
// do not line up): random densities in two blocks, x < 3 and x >= 6, zero between.
DensityGrid twoBlocks() {
    DensityGrid g{9, 6, 80, {}};
    Pcg32 rng(5);
    for (int z = 0; z < g.nz; ++z)
        for (int y = 0; y < g.ny; ++y)
            for (int x = 0; x < g.nx; ++x) g.density.push_back(x < 3 || x >= 6 ? 0.1f + 2 * rng.uniform() : 0.0f);
    return g;
}

GridMedium mediumOf(const DensityGrid& g) { return GridMedium(g, kGridSigmaA, kGridSigmaS, Transform{}, HenyeyGreenstein(0)); }

TEST(GridMedium, MajorantsBoundTheDensityEverywhere) {
    const DensityGrid g = twoBlocks();
    const GridMedium m = mediumOf(g);
    const MajorantGrid majorants = densityMajorants(g, kSigmaT);
    ASSERT_EQ(majorants.nx, 9);
    ASSERT_EQ(majorants.nz, 64);
    Pcg32 rng(11);
    for (int i = 0; i < 400000; ++i) {
        const Vec3f p{rng.uniform(), rng.uniform(), rng.uniform()};
        const int cx = int(p.x * 9), cy = int(p.y * 6), cz = int(p.z * 64);
        ASSERT_LE(kSigmaT * m.density(p), majorants.at(cx, cy, cz) * (1 + 1e-6f)) << p.x << " " << p.y << " " << p.z;
    }
    // On the faces between cells the density must be below both cells' majorants.
    for (int x = 1; x < 9; ++x)
        for (int i = 0; i < 1000; ++i) {
            const Vec3f p{x / 9.0f, rng.uniform(), rng.uniform()};
            const int cy = int(p.y * 6), cz = int(p.z * 64);
            for (int cx : {x - 1, x}) ASSERT_LE(kSigmaT * m.density(p), majorants.at(cx, cy, cz) * (1 + 1e-6f));
        }
    // Samples 3..5 are zero: cell 4 lies beyond the reach of samples 2 and 6, so it is empty.
    for (int z = 0; z < 64; ++z)
        for (int y = 0; y < 6; ++y) {
            EXPECT_EQ(majorants.at(4, y, z), 0.0f);
            EXPECT_GT(majorants.at(3, y, z), 0.0f);  // sample 2 reaches into x cell 3
        }
}

// An oblique ray from outside the box through both blocks and the empty gap: ratio tracking
// (transmittance) and delta tracking (the share of paths an absorber lets through) against
// exp(-sigma_t * the density's integral) by the midpoint rule, per channel.
TEST(GridMedium, TrackingThroughEmptyRegionsMatchesQuadrature) {
    const DensityGrid g = twoBlocks();
    const Vec3f sigmaA{0.4f, 0.7f, 1.0f};
    const GridMedium m(g, sigmaA, {}, Transform{}, HenyeyGreenstein(0));
    const Vec3f o{-0.2f, 0.3f, 0.2f}, d = normalize(Vec3f{1.4f, 0.2f, 0.5f});
    const float length = 1.8f;
    const double depth = test::midpointDepth(o, d, length, 40000, {0, 0, 0}, {1, 1, 1}, [&](Vec3f p) { return m.density(p); });
    ASSERT_GT(depth * sigmaA.z, 0.5);  // thick enough to matter, thin enough for a tight estimate
    ASSERT_LT(depth * sigmaA.z, 2.0);
    constexpr int kSamples = 200000;
    Pcg32 rng(3);
    Vec3f transmitted;
    double passed = 0;
    for (int i = 0; i < kSamples; ++i) {
        transmitted += m.transmittance(o, d, length, rng);
        passed += !isBlack(m.sample(o, d, length, 2, rng).weight);
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(transmitted[c] / kSamples / std::exp(-sigmaA[c] * depth), 1.0, 0.01) << "channel " << c;
    EXPECT_NEAR(passed / kSamples / std::exp(-sigmaA.z * depth), 1.0, 0.02);
}

}  // namespace
}  // namespace lenslab
