// The parts of several wavelengths per sample (render/HeroWavelengths.h) against hand counts: the
// filter densities the weights use match the offsets the filter draws, a sample's wavelengths form
// the same set whichever of them is its own, a dispersion-free sample scores the plain mean of its
// wavelengths in its own pixel, one landing in a neighbour moves that wavelength there whole, and
// a frame's splats sum to the same bits whatever order its tiles finish in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "film/PixelFilter.h"
#include "film/SpectralSensor.h"
#include "render/HeroWavelengths.h"
#include "render/SplatImage.h"

namespace lenslab {
namespace {

FilterSpec filterOf(FilterType type, double width) {
    FilterSpec s;
    s.type = type;
    s.xwidth = s.ywidth = width;
    return s;
}

// The radical inverse in base 2: evenly spread u for the histograms.
float vanDerCorput(unsigned i) {
    unsigned r = 0;
    for (int b = 0; b < 32; ++b, i >>= 1) r = (r << 1) | (i & 1u);
    return float(double(r) / 4294967296.0);
}

}  // namespace

// A histogram of sample()'s x offsets against densityX, and the weight densityX reports against the
// weight sample() gave there, for a filter with negative lobes.
TEST(HeroWavelengths, FilterDensityMatchesTheDrawnOffsets) {
    for (const FilterSpec& spec : {filterOf(FilterType::Gaussian, 2), filterOf(FilterType::Mitchell, 2)}) {
        const PixelFilter filter(spec);
        constexpr int kBins = 40, kSamples = 1 << 18;
        const double width = spec.xwidth, binWidth = 2 * width / kBins;
        std::vector<double> histogram(kBins, 0);
        int signMismatches = 0;
        for (int i = 0; i < kSamples; ++i) {
            float dx, dy;
            const float weight = filter.sample(vanDerCorput(unsigned(i)), 0.5f, dx, dy);
            const int bin = std::clamp(int((dx + width) / binWidth), 0, kBins - 1);
            histogram[std::size_t(bin)] += 1.0 / (kSamples * binWidth);
            float wx, wy;
            filter.densityX(dx, wx);
            filter.densityY(dy, wy);
            signMismatches += std::fabs(wx * wy - weight) > 1e-5f * std::fabs(weight);
        }
        EXPECT_LT(signMismatches, kSamples / 1000);  // a bin edge rounded differently
        for (int b = 0; b < kBins; ++b) {
            float w;
            const double x = -width + (b + 0.5) * binWidth, density = filter.densityX(x, w);
            EXPECT_NEAR(histogram[std::size_t(b)], density, 0.02 * filter.densityX(0, w) + 1e-3) << "x = " << x;
        }
        float w;
        EXPECT_EQ(filter.densityX(width + 0.01, w), 0.0f);
        EXPECT_EQ(w, 0.0f);
    }
}

// n wavelengths a sample: each 1 / n apart in the distribution, so that the set drawn from u is
// the one drawn from u + j / n (mod 1): any of them may have been the sample's own.
TEST(HeroWavelengths, WavelengthSetIsTheSameWhicheverIsFirst) {
    const SpectralSensor sensor;
    for (int n : {2, 3, 8})
        for (float u : {0.0f, 0.13f, 0.61f, 0.97f}) {
            std::vector<WavelengthSample> first(std::size_t(n), WavelengthSample{});
            sensor.sample(u, n, first.data());
            std::vector<double> a;
            for (const WavelengthSample& w : first) a.push_back(w.nm);
            EXPECT_EQ(first[0].nm, sensor.sample(u).nm);
            std::sort(a.begin(), a.end());
            for (int j = 1; j < n; ++j) {
                float v = u + float(j) / float(n);
                if (v >= 1) v -= 1;
                std::vector<WavelengthSample> other(std::size_t(n), WavelengthSample{});
                sensor.sample(v, n, other.data());
                std::vector<double> b;
                for (const WavelengthSample& w : other) b.push_back(w.nm);
                std::sort(b.begin(), b.end());
                EXPECT_EQ(a, b) << n << " wavelengths, u = " << u << ", from the " << j << "th";
            }
        }
}

// Every wavelength landing on the sample's own film point (no dispersion): the own pixel gets the
// ray's weight (response / density) times the mean of the wavelengths' film values, no splats.
TEST(HeroWavelengths, UndispersedSampleScoresTheMeanInItsOwnPixel) {
    const SpectralSensor sensor;
    const PixelFilter filter(filterOf(FilterType::Gaussian, 2));
    const PixelRect area{0, 0, 16, 16};
    const Vec3f radiance{0.8f, 0.3f, 0.1f};
    constexpr int kCount = 4;
    WavelengthSample wavelengths[kCount];
    sensor.sample(0.3f, kCount, wavelengths);
    FilmLanding landings[kCount];
    for (FilmLanding& l : landings) l = {7.3, 8.6, 2.5, 5.0};
    SplatBuffer splats;
    float w;
    const float ownWeight = filter.densityX(7.3 - 7.5, w) > 0 ? w : 0.0f;
    const Vec3f own = heroWavelengthEstimate(sensor, filter, area, 7, 8, ownWeight, radiance, wavelengths, landings,
                                             kCount, 1.0f / 16, splats);
    Vec3f expected{0, 0, 0};
    for (const WavelengthSample& wl : wavelengths) expected = expected + (5.0f / 2.5f / kCount) * sensor.toRgb(radiance, wl);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(own[c], expected[c], 1e-5 * std::fabs(expected[c]) + 1e-7) << c;
    EXPECT_TRUE(splats.empty());
}

// Box filter, two wavelengths of equal density, the second landing in the pixel to the right: the
// own pixel keeps the first's value only and the neighbour receives the second's, times the splat
// scale (a sample's share among a pixel's spp).
TEST(HeroWavelengths, WavelengthLandingInANeighbourMovesThere) {
    const SpectralSensor sensor;
    const PixelFilter filter(filterOf(FilterType::Box, 0.5));
    const PixelRect area{0, 0, 16, 16};
    const Vec3f radiance{0.2f, 0.5f, 0.9f};
    WavelengthSample wavelengths[2];
    sensor.sample(0.42f, 2, wavelengths);
    const FilmLanding landings[2] = {{5.5, 6.5, 1.0, 1.0}, {6.25, 6.5, 1.0, 1.0}};
    SplatBuffer splats;
    const float scale = 1.0f / 16;
    const Vec3f own =
        heroWavelengthEstimate(sensor, filter, area, 5, 6, 1.0f, radiance, wavelengths, landings, 2, scale, splats);
    const Vec3f first = 0.5f * sensor.toRgb(radiance, wavelengths[0]), second = 0.5f * sensor.toRgb(radiance, wavelengths[1]);
    ASSERT_FALSE(splats.empty());
    const PixelRect& box = splats.box();
    const auto at = [&](int x, int y, int c) {
        if (x < box.x0 || x >= box.x1 || y < box.y0 || y >= box.y1) return 0.0f;
        return splats.rgb()[(std::size_t(y - box.y0) * std::size_t(box.x1 - box.x0) + std::size_t(x - box.x0)) * 3 + c];
    };
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(own[c], first[c], 1e-6) << c;
        EXPECT_NEAR(at(6, 6, c), scale * second[c], 1e-7) << c;
        double elsewhere = 0;
        for (int y = box.y0; y < box.y1; ++y)
            for (int x = box.x0; x < box.x1; ++x)
                if (x != 6 || y != 6) elsewhere += std::fabs(at(x, y, c));
        EXPECT_EQ(elsewhere, 0.0) << c;
    }
}

// Tiles finishing in any order, one of them twice (MPI re-queues a lost worker's tile): the same
// sum to the bit as in tile order.
TEST(HeroWavelengths, SplatsSumToTheSameBitsInAnyTileOrder) {
    const auto tileSplats = [](int tile) {
        SplatBuffer b;
        for (int k = 0; k < 5; ++k)
            b.add(3 * tile + k % 4, tile + k / 2, Vec3f{0.1f * float(k + 1), 1e-7f * float(tile + 1), 3.3f / float(k + tile + 1)});
        return b;
    };
    constexpr int kTiles = 6;
    SplatImage ordered(kTiles), shuffled(kTiles);
    for (int t = 0; t < kTiles; ++t) ordered.tileDone(std::size_t(t), tileSplats(t));
    for (int t : {4, 1, 5, 1, 0, 3, 2}) shuffled.tileDone(std::size_t(t), tileSplats(t));
    EXPECT_EQ(ordered.sum().box().x0, shuffled.sum().box().x0);
    EXPECT_EQ(ordered.sum().rgb(), shuffled.sum().rgb());
    SplatImage missing(kTiles);
    for (int t = 1; t < kTiles; ++t) missing.tileDone(std::size_t(t), tileSplats(t));
    EXPECT_THROW(missing.sum(), std::logic_error);
}

}  // namespace lenslab
