// pbrt-v4's cloud medium: its density stays within the bound its majorant assumes, and ratio
// tracking through it gives the transmittance exp(-integral of sigma_t) found by quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "media/CloudMedium.h"

namespace lenslab {
namespace {

const Vec3f kCloudSigmaA{0.2f, 0.5f, 1.0f}, kCloudSigmaS{0.8f, 0.8f, 0.8f};

CloudMedium unitCloud(CloudShape shape = {}) {
    return CloudMedium(shape, kCloudSigmaA, kCloudSigmaS, {0, 0, 0}, {1, 1, 1}, Transform{}, HenyeyGreenstein(0));
}

TEST(CloudMedium, DensityStaysWithinTheMajorantsBound) {
    CloudShape dense;
    dense.density = 20;
    dense.wispiness = 5;
    for (const CloudShape& shape : {CloudShape{}, dense}) {
        const CloudMedium cloud = unitCloud(shape);
        float lowest = 1, highest = 0;
        for (int i = 0; i < 40; ++i)
            for (int j = -10; j < 50; ++j)  // y beyond both faces too
                for (int k = 0; k < 40; ++k) {
                    const float d = cloud.density({i / 40.0f, j / 40.0f, k / 40.0f});
                    ASSERT_GE(d, 0.0f);
                    ASSERT_LE(d, 1.0f);
                    lowest = std::min(lowest, d);
                    highest = std::max(highest, d);
                }
        EXPECT_LT(lowest, 0.1f);  // a cloud, not a uniform fog
        EXPECT_EQ(highest, 1.0f);  // solid below y = 0.5
    }
}

// Rays along x through the unit box at several heights: the mean of ratio tracking's estimates
// against exp(-sigma_t * integral of the density), the integral by the midpoint rule.
TEST(CloudMedium, RatioTrackingMatchesQuadrature) {
    const CloudMedium cloud = unitCloud();
    Pcg32 rng(7);
    for (const float y : {0.3f, 0.55f, 0.7f, 0.85f}) {
        const Vec3f o{-0.5f, y, 0.4f}, d{1, 0, 0};
        constexpr int kSteps = 4000;
        double optical = 0;  // of the density alone
        for (int i = 0; i < kSteps; ++i) optical += cloud.density({(i + 0.5f) / kSteps, y, 0.4f});
        optical /= kSteps;
        constexpr int kSamples = 40000;
        Vec3f sum;
        for (int i = 0; i < kSamples; ++i) sum += cloud.transmittance(o, d, 2, rng);
        for (int c = 0; c < 3; ++c) {
            const double expected = std::exp(-(kCloudSigmaA[c] + kCloudSigmaS[c]) * optical);
            EXPECT_NEAR(sum[c] / kSamples / expected, 1.0, 0.02) << "y " << y << " channel " << c;
        }
    }
}

}  // namespace
}  // namespace lenslab
