// pbrt-v3's pixel filters: their profiles, the offsets filter importance sampling draws (a
// histogram against the normalised |f|) and the signed weights that keep a pixel's mean exact.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "film/PixelFilter.h"
#include "prescription/Pi.h"
#include "sampling/Sampling.h"

namespace lenslab {
namespace {

FilterSpec spec(FilterType type, double width) {
    FilterSpec s;
    s.type = type;
    s.xwidth = s.ywidth = width;
    return s;
}

// pbrt-v3's defaults.
const FilterSpec kFilters[] = {spec(FilterType::Box, 0.5), spec(FilterType::Gaussian, 2), spec(FilterType::Triangle, 2),
                               spec(FilterType::Mitchell, 2), spec(FilterType::Sinc, 4)};
const char* kFilterNames[] = {"box", "gaussian", "triangle", "mitchell", "sinc"};

TEST(PixelFilters, ProfilesMatchTheirDefinitions) {
    const FilterSpec& g = kFilters[1];
    EXPECT_NEAR(PixelFilter::profile(g, 2, 1), std::exp(-2.0) - std::exp(-8.0), 1e-12);
    EXPECT_NEAR(PixelFilter::profile(kFilters[2], 2, 0.5), 1.5, 1e-12);
    // Mitchell-Netravali with B = C = 1/3 over [-2, 2] cubic units: (6 - 2B) / 6 at the centre,
    // B / 6 at one unit, zero at two, negative in between.
    const FilterSpec& m = kFilters[3];
    EXPECT_NEAR(PixelFilter::profile(m, 2, 0), (6 - 2.0 / 3) / 6, 1e-12);
    EXPECT_NEAR(PixelFilter::profile(m, 2, 1), 1.0 / 18, 1e-12);
    EXPECT_NEAR(PixelFilter::profile(m, 2, 2), 0, 1e-12);
    EXPECT_LT(PixelFilter::profile(m, 2, 1.5), 0);
    // Lanczos: sinc(x) sinc(x / tau); sinc(0.5) sinc(1/6) = (2 / pi) (3 / pi).
    const FilterSpec& l = kFilters[4];
    EXPECT_NEAR(PixelFilter::profile(l, 4, 0.5), 6 / (kPi * kPi), 1e-9);
    EXPECT_NEAR(PixelFilter::profile(l, 4, 1), 0, 1e-9);
    EXPECT_LT(PixelFilter::profile(l, 4, 1.5), 0);
    EXPECT_EQ(PixelFilter::profile(l, 4, 4.5), 0);
}

// The integral of the profile over [a, b], by a fine midpoint rule.
double integral(const FilterSpec& s, double width, double a, double b, bool absolute) {
    const int n = 2000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double f = PixelFilter::profile(s, width, a + (i + 0.5) * (b - a) / n);
        sum += absolute ? std::fabs(f) : f;
    }
    return sum * (b - a) / n;
}

TEST(PixelFilters, OffsetsFollowTheAbsoluteProfile) {
    for (int k = 0; k < 5; ++k) {
        const FilterSpec& s = kFilters[k];
        const PixelFilter filter(s);
        const double w = s.xwidth;
        EXPECT_EQ(filter.radius(), w);
        const int bins = 16, n = 1 << 16;
        std::vector<double> histogram(bins, 0);
        for (int i = 0; i < n; ++i) {
            float dx, dy;
            filter.sample((i + 0.5f) / n, 0.5f, dx, dy);
            ASSERT_LE(std::fabs(dx), w) << kFilterNames[k];
            histogram[std::min(bins - 1, int((dx + w) / (2 * w) * bins))] += 1.0 / n;
        }
        const double total = integral(s, w, -w, w, true);
        for (int b = 0; b < bins; ++b) {
            const double a = -w + 2 * w * b / bins, expected = integral(s, w, a, a + 2 * w / bins, true) / total;
            EXPECT_NEAR(histogram[b], expected, 2e-3) << kFilterNames[k] << " bin " << b;
        }
    }
}

// Weighted by the signed weights, samples reproduce the filter itself: the weights average 1 (a
// constant comes out exact) and the weighted mean of x^2 is the filter's second moment. The
// weight is a product of an x and a y part, so means over a fine grid in x at a fixed y (divided
// by the y part's mean, found the same way) stand for means over the whole square.
TEST(PixelFilters, SignedWeightsReproduceTheFilter) {
    for (int k = 0; k < 5; ++k) {
        const FilterSpec& s = kFilters[k];
        const PixelFilter filter(s);
        const double w = s.xwidth;
        const int n = 1 << 16;
        const float centre = 0.5f;
        float dx, dy;
        const double both = filter.sample(centre, centre, dx, dy);  // x part (centre) * y part (centre)
        double xWeights = 0, yWeights = 0, xMoment = 0, negative = 0;
        for (int i = 0; i < n; ++i) {
            const float u = (i + 0.5f) / n;
            const float wx = filter.sample(u, centre, dx, dy);
            xWeights += wx;
            xMoment += wx * dx * dx;
            negative += wx < 0;
            yWeights += filter.sample(centre, u, dx, dy);
        }
        // mean(x part) mean(y part) = (xWeights / n) (yWeights / n) / both
        EXPECT_NEAR(xWeights / n * yWeights / n / both, 1.0, 1e-3) << kFilterNames[k];
        double fx2 = 0;
        const int m = 4000;
        for (int i = 0; i < m; ++i) {
            const double x = -w + (i + 0.5) * 2 * w / m;
            fx2 += x * x * PixelFilter::profile(s, w, x) * 2 * w / m;
        }
        const double moment = fx2 / integral(s, w, -w, w, false);
        // The y part (at the centre) multiplies both sums alike.
        EXPECT_NEAR(xMoment / xWeights, moment, 1e-3 * std::max(1.0, moment)) << kFilterNames[k];
        const bool lobes = s.type == FilterType::Mitchell || s.type == FilterType::Sinc;
        EXPECT_EQ(negative > 0, lobes) << kFilterNames[k];
    }
}

TEST(PixelFilters, MitchellWeightsAreNegativeInItsOuterLobes) {
    const PixelFilter filter(kFilters[3]);
    float dx, dy;
    EXPECT_GT(filter.sample(0.5f, 0.5f, dx, dy), 0);
    EXPECT_NEAR(dx, 0, 0.02);
    EXPECT_LT(filter.sample(0.01f, 0.5f, dx, dy), 0);
    EXPECT_LT(dx, -1.0);
}

// Pixels of 16 samples each from the filter: a flat field comes out exact in every pixel, and a
// step edge converges to the filtered value (the bias shrinks as 1 / samples).
TEST(PixelFilters, PixelsOfAFlatFieldAreExactAndEdgesConverge) {
    for (int k = 0; k < 5; ++k) {
        const FilterSpec& s = kFilters[k];
        const PixelFilter filter(s);
        const double w = s.xwidth, edge = 0.3 * w;  // radiance 1 for offsets x > edge, else 0
        const double filtered = integral(s, w, edge, w, false) / integral(s, w, -w, w, false);
        const double absolute = integral(s, w, edge, w, true) / integral(s, w, -w, w, true);
        const int pixels = 20000, spp = 16;
        Pcg32 rng(3);
        double edgeSum = 0;
        for (int p = 0; p < pixels; ++p) {
            FilteredPixel flat, step;
            for (int i = 0; i < spp; ++i) {
                float dx, dy;
                const float weight = filter.sample(rng.uniform(), rng.uniform(), dx, dy);
                flat.add(weight, {0.25f, 0.5f, 2});
                step.add(weight, dx > edge ? Vec3f{1, 1, 1} : Vec3f{});
            }
            ASSERT_NEAR(flat.value().x, 0.25f, 1e-6f) << kFilterNames[k];
            ASSERT_NEAR(flat.value().z, 2.0f, 1e-5f) << kFilterNames[k];
            edgeSum += step.value().x;
        }
        const double bias = (absolute - filtered) / spp;
        EXPECT_NEAR(edgeSum / pixels, filtered + bias, 0.01) << kFilterNames[k];
        EXPECT_LT(std::fabs(bias), 0.01) << kFilterNames[k];
    }
}

}  // namespace
}  // namespace lenslab
