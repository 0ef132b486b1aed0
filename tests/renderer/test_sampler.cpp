// The pixel sampler: every pair of camera dimensions used together (film x/y, lens u/v, film against
// lens) is stratified, the time is stratified on its own, and no dimension repeats another.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "sampling/Sampling.h"

namespace lenslab {
namespace {

using Points = std::vector<std::array<float, 4>>;  // film x, film y, lens u, lens v

Points pixelSamples(std::uint64_t pixelSeed, int count) {
    const PixelSampler sampler(pixelSeed);
    Points p;
    for (int i = 0; i < count; ++i) {
        const PixelSample s = sampler(std::uint32_t(i));
        p.push_back({s.filmX, s.filmY, s.lensU, s.lensV});
    }
    return p;
}

// The pairs of dimensions whose points leave a cell of the side x side grid empty.
std::vector<std::pair<int, int>> unstratifiedPairs(const Points& points, int side) {
    std::vector<std::pair<int, int>> bad;
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
            std::set<std::pair<int, int>> cells;
            for (const auto& p : points) cells.insert({int(p[a] * side), int(p[b] * side)});
            if (int(cells.size()) != side * side) bad.push_back({a, b});
        }
    return bad;
}

TEST(PixelSampler, EveryPairOfDimensionsFillsEveryCell) {
    for (std::uint64_t seed : {0ull, 1ull, 0x5eedull, 123456789ull}) {
        EXPECT_TRUE(unstratifiedPairs(pixelSamples(seed, 256), 16).empty()) << "seed " << seed << ", 256 samples";
        EXPECT_TRUE(unstratifiedPairs(pixelSamples(seed, 16), 4).empty()) << "seed " << seed << ", 16 samples";
    }
}

TEST(PixelSampler, ALensDimensionCopiedFromAnotherFailsTheCheck) {
    // The check itself must see a repeated dimension: lens v a copy of lens u fills 16 of 256 cells.
    Points copied = pixelSamples(7, 256);
    for (auto& p : copied) p[3] = p[2];
    const auto bad = unstratifiedPairs(copied, 16);
    ASSERT_EQ(bad.size(), 1u);
    EXPECT_EQ(bad[0], std::make_pair(2, 3));
    std::set<std::pair<int, int>> cells;
    for (const auto& p : copied) cells.insert({int(p[2] * 16), int(p[3] * 16)});
    EXPECT_EQ(cells.size(), 16u);
}

TEST(PixelSampler, TwoSamplesFallInOppositeHalvesOfEveryDimension) {
    for (std::uint64_t seed : {0ull, 9ull, 77ull}) {
        const Points p = pixelSamples(seed, 2);
        for (int d = 0; d < 4; ++d) EXPECT_NE(p[0][d] < 0.5f, p[1][d] < 0.5f) << "dimension " << d;
    }
}

TEST(PixelSampler, PixelsDrawDifferentPointsAndEachIsAPureFunctionOfItsSeed) {
    const Points a = pixelSamples(1, 16), again = pixelSamples(1, 16), b = pixelSamples(2, 16);
    EXPECT_EQ(a, again);
    int same = 0;
    for (int i = 0; i < 16; ++i)
        for (int d = 0; d < 4; ++d) same += a[i][d] == b[i][d];
    EXPECT_LT(same, 4);
    for (const auto& p : a)
        for (float v : p) {
            EXPECT_GE(v, 0.0f);
            EXPECT_LT(v, 1.0f);
        }
}

TEST(PixelSampler, SampleMeansConvergeToOneHalf) {
    // An unbiased scramble: over many pixels every dimension averages 1/2 and pairs are uncorrelated.
    double mean[4] = {0, 0, 0, 0}, cross = 0;
    const int pixels = 2000, spp = 16;
    for (int px = 0; px < pixels; ++px)
        for (const auto& p : pixelSamples(mix64(px), spp)) {
            for (int d = 0; d < 4; ++d) mean[d] += p[d];
            cross += (p[0] - 0.5) * (p[2] - 0.5);
        }
    for (double m : mean) EXPECT_NEAR(m / (pixels * spp), 0.5, 0.005);
    EXPECT_NEAR(cross / (pixels * spp), 0.0, 0.002);
}

std::vector<float> times(std::uint64_t pixelSeed, int count) {
    const PixelSampler sampler(pixelSeed);
    std::vector<float> t;
    for (int i = 0; i < count; ++i) t.push_back(sampler(std::uint32_t(i)).time);
    return t;
}

TEST(PixelSampler, AnyPowerOfTwoSamplesFallOneInEachSliceOfTheShutterInterval) {
    for (std::uint64_t seed : {0ull, 3ull, 0x5eedull})
        for (int count : {2, 16, 256}) {
            std::set<int> slices;
            for (float t : times(seed, count)) slices.insert(int(t * count));
            EXPECT_EQ(int(slices.size()), count) << "seed " << seed << ", " << count << " samples";
        }
}

// The 4 x 4 cells that 16 samples of (time, dimension d) fill, on average over many pixels. A time
// that shared the lens's matrix (scrambled apart, but nested alike) would fill only 4: each quarter
// of the shutter would always meet the same quarter of the lens. So would any time stratified at
// every power of two without its index shuffle: its quarter, like the lens's, is fixed by i mod 4.
double cellsFilledWithTime(int d, bool timeCopiesLensU) {
    const int pixels = 500;
    double filled = 0;
    for (int px = 0; px < pixels; ++px) {
        const PixelSampler sampler(mix64(px));
        std::set<std::pair<int, int>> cells;
        for (std::uint32_t i = 0; i < 16; ++i) {
            const PixelSample s = sampler(i);
            const float other[4] = {s.filmX, s.filmY, s.lensU, s.lensV};
            const float t = timeCopiesLensU ? PixelSampler(mix64(px) + 99)(i).lensU : s.time;
            cells.insert({int(t * 4), int(other[d] * 4)});
        }
        filled += double(cells.size());
    }
    return filled / pixels;
}

TEST(PixelSampler, TimeIsIndependentOfFilmAndLens) {
    // With the shuffle each aligned block of 4 samples meets every quarter of the other dimension once
    // (a permutation), and the 4 blocks' permutations are drawn apart: a cell stays empty with
    // probability (3/4)^4, so 16 samples fill 10.9 of 16 cells on average.
    for (int d = 0; d < 4; ++d) EXPECT_NEAR(cellsFilledWithTime(d, false), 16 * (1 - std::pow(0.75, 4)), 0.3) << "dimension " << d;
    EXPECT_LT(cellsFilledWithTime(2, true), 4.5);  // the check sees a time that repeats the lens's matrix
    double mean = 0, cross = 0;
    for (int px = 0; px < 2000; ++px) {
        const PixelSampler sampler(mix64(px));
        for (std::uint32_t i = 0; i < 16; ++i) {
            const PixelSample s = sampler(i);
            mean += s.time;
            cross += (s.time - 0.5) * (s.lensU - 0.5);
        }
    }
    EXPECT_NEAR(mean / 32000, 0.5, 0.005);
    EXPECT_NEAR(cross / 32000, 0.0, 0.002);
}

// The spectral film's wavelength is a sixth dimension, padded apart from the time: were it drawn
// with the time's seeds, a motion-blurred spectral render would tie colour to the moment (every
// sample's wavelength equal to its time). Like the time against the lens, 16 samples of (time,
// wavelength) fill 16 (1 - (3/4)^4) = 10.9 of the 4 x 4 cells on average, not the diagonal's 4; and
// any aligned power of two of them falls one in each slice of the spectrum.
TEST(PixelSampler, WavelengthIsIndependentOfTime) {
    const int pixels = 500;
    double filled = 0, cross = 0;
    for (int px = 0; px < pixels; ++px) {
        const PixelSampler sampler(mix64(px));
        std::set<std::pair<int, int>> cells;
        for (std::uint32_t i = 0; i < 16; ++i) {
            const PixelSample s = sampler(i);
            cells.insert({int(s.time * 4), int(s.wavelength * 4)});
            cross += (s.time - 0.5) * (s.wavelength - 0.5);
        }
        filled += double(cells.size());
    }
    EXPECT_NEAR(filled / pixels, 16 * (1 - std::pow(0.75, 4)), 0.3);
    EXPECT_NEAR(cross / (16 * pixels), 0.0, 0.004);  // 1/12 were they equal
    for (int count : {4, 64}) {
        const PixelSampler sampler(mix64(7));
        std::set<int> slices;
        for (std::uint32_t i = 0; i < std::uint32_t(count); ++i) slices.insert(int(sampler(i).wavelength * count));
        EXPECT_EQ(int(slices.size()), count) << count << " samples";
    }
}

}  // namespace
}  // namespace lenslab
