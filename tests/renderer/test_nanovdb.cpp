// pbrt-v4's nanovdb medium: NanoVDB files written here (NanoVdbTestFile.h) read back voxel for voxel
// across leaves, lower, upper and root tiles; trilinear lookups match an independent interpolation;
// the box and the transmittance through a constant block match closed forms; truncated, corrupted
// and unsupported files are errors naming the file, never crashes.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "MidpointDepth.h"
#include "NanoVdbTestFile.h"
#include "TempDir.h"
#include "TestScenes.h"
#include "media/NanoVdbMedium.h"
#include "scene/SceneDescription.h"

namespace lenslab {
namespace {

using test::Coord;
using test::NanoVdbTestGrid;

// Voxels in several leaves (x = 7 and 8 lie in neighbouring leaves), in a second lower node (x 130),
// at negative coordinates and far away (other root tiles), and the three kinds of constant tile.
NanoVdbTestGrid spreadGrid() {
    NanoVdbTestGrid g;
    g.background = 0.01f;
    g.voxels = {{{0, 0, 0}, 1},   {{1, 0, 0}, 2},    {{2, 0, 0}, 3},    {{3, 0, 0}, 4},       {{7, 1, 2}, 5},
                {{8, 1, 2}, 7},   {{7, 2, 2}, 6},    {{8, 2, 3}, 8},    {{7, 1, 3}, 0.5f},    {{-1, -1, -1}, 9},
                {{130, 5, 5}, 0.25f}, {{5000, 0, 0}, 3}};
    g.tiles = {{{16, 16, 16}, 1, 0.5f}, {{256, 0, 0}, 2, 0.125f}, {{-5000, 0, 0}, 3, 0.0625f}};
    return g;
}

// What the grid holds at c, from its description alone.
float expectedVoxel(const NanoVdbTestGrid& g, const Coord& c) {
    const auto it = g.voxels.find(c);
    if (it != g.voxels.end()) return it->second;
    for (const auto& t : g.tiles) {
        const int size = t.level == 1 ? 8 : t.level == 2 ? 128 : 4096;
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && (c[a] & ~(size - 1)) == (t.origin[a] & ~(size - 1));
        if (inside) return t.value;
    }
    return g.background;
}

NanoVdbGrid readBack(const std::string& bytes, const std::string& grid = "density") {
    std::istringstream in(bytes);
    const std::optional<NanoVdbGrid> g = readNanoVdbGrid(in, grid, "t.nvdb");
    if (!g) throw std::runtime_error("no grid " + grid);
    return *g;
}

// The reader's error message for these bytes, or "(no error)".
std::string vdbErrorOf(const std::string& bytes, const std::string& grid = "density") {
    std::istringstream in(bytes);
    try {
        readNanoVdbGrid(in, grid, "t.nvdb");
    } catch (const NanoVdbError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(NanoVdb, VoxelsReadBackThroughEveryLevelOfTheTree) {
    const NanoVdbTestGrid g = spreadGrid();
    const NanoVdbGrid read = readBack(test::nanoVdbFile({g}));
    EXPECT_EQ(read.name, "density");
    EXPECT_EQ(read.root.size(), 4u);  // around the origin, below it, at x 4096..8191, and the constant root tile
    EXPECT_EQ(read.upperChild.size(), 3u * kNanoVdbUpperSlots);
    // Lower nodes: x 0..127 and 128..255 near the origin, one below it, one at x 5000.
    EXPECT_EQ(read.lowerChild.size(), 4u * kNanoVdbLowerSlots);
    // Leaves: x 0..7 and 8..15 near the origin, x 128..135, one below the origin, one at x 5000.
    EXPECT_EQ(read.leafValues.size(), 5u * kNanoVdbLeafVoxels);
    for (const auto& [c, v] : g.voxels) EXPECT_EQ(read.voxel(c[0], c[1], c[2]), v) << c[0] << " " << c[1] << " " << c[2];
    const std::vector<Coord> others = {{16, 16, 16}, {23, 23, 23}, {24, 16, 16}, {15, 16, 16},   {256, 0, 0},
                                       {383, 127, 127}, {384, 0, 0}, {-5000, 0, 0}, {-8192, 4095, 4095}, {-4096, 0, 0},
                                       {4, 0, 0},   {6, 1, 2},   {0, 0, -1}, {100000, -100000, 7}, {-2, -1, -1}};
    for (const Coord& c : others) EXPECT_EQ(read.voxel(c[0], c[1], c[2]), expectedVoxel(g, c)) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_EQ(read.activeMin, (std::array<int, 3>{-8192, -1, -1}));
    EXPECT_EQ(read.activeMax, (std::array<int, 3>{5000, 4095, 4095}));
    EXPECT_EQ(read.smallest, 0.01f);
    EXPECT_EQ(read.largest, 9.0f);
}

// Trilinear between voxel centres: at centres the voxel's own value; between them the weighted sum
// of the eight corners, computed here from the grid's description.
TEST(NanoVdb, InterpolationIsTrilinearBetweenVoxelCentres) {
    const NanoVdbTestGrid g = spreadGrid();
    const NanoVdbGrid read = readBack(test::nanoVdbFile({g}));
    for (const auto& [c, v] : g.voxels) EXPECT_FLOAT_EQ(read.interpolate(c[0], c[1], c[2]), v);
    EXPECT_FLOAT_EQ(read.interpolate(1.25, 0, 0), 0.75f * 2 + 0.25f * 3);
    EXPECT_FLOAT_EQ(read.interpolate(7.5, 1, 2), 0.5f * 5 + 0.5f * 7);  // across the leaves' boundary
    Pcg32 rng(3);
    for (int n = 0; n < 200; ++n) {
        const double x = 6 + 3 * rng.uniform(), y = 0.5 + 2.5 * rng.uniform(), z = 1 + 3 * rng.uniform();
        const int i = int(std::floor(x)), j = int(std::floor(y)), k = int(std::floor(z));
        const double fx = x - i, fy = y - j, fz = z - k;
        double expected = 0;
        for (int di = 0; di < 2; ++di)
            for (int dj = 0; dj < 2; ++dj)
                for (int dk = 0; dk < 2; ++dk)
                    expected += (di ? fx : 1 - fx) * (dj ? fy : 1 - fy) * (dk ? fz : 1 - fz) *
                                expectedVoxel(g, {i + di, j + dj, k + dk});
        EXPECT_NEAR(read.interpolate(x, y, z), expected, 1e-5) << x << " " << y << " " << z;
    }
}

// An 8^3 block of density 0.5 (a lower node's tile), voxels 0.25 wide, index origin at (1, 0, 0),
// the medium moved up by 5: NanoVDB's box runs from voxel 0 to voxel 7's far side.
NanoVdbTestGrid blockGrid() {
    NanoVdbTestGrid g;
    g.tiles = {{{0, 0, 0}, 1, 0.5f}};
    g.matrix[0][0] = g.matrix[1][1] = g.matrix[2][2] = 0.25;
    g.translation[0] = 1;
    return g;
}

const Vec3f kVdbSigmaA{0.5f, 1, 2};

NanoVdbMedium blockMedium() {
    return NanoVdbMedium(readBack(test::nanoVdbFile({blockGrid()})), kVdbSigmaA, {}, translate(0, 0, 5), HenyeyGreenstein(0));
}

TEST(NanoVdb, BoxIsTheActiveVoxelsMappedToTheMediumsSpace) {
    NanoVdbTestGrid g = spreadGrid();
    g.matrix[0][0] = 0.5;
    g.matrix[1][1] = 0.25;
    g.matrix[2][2] = 2;
    g.translation[0] = 1;
    g.translation[1] = 2;
    g.translation[2] = 3;
    const NanoVdbMedium m(readBack(test::nanoVdbFile({g})), {1, 1, 1}, {1, 1, 1}, Transform{}, HenyeyGreenstein(0));
    Vec3f lo, hi;
    m.bounds(lo, hi);
    EXPECT_FLOAT_EQ(lo.x, 1 + 0.5f * -8192);
    EXPECT_FLOAT_EQ(lo.y, 2 + 0.25f * -1);
    EXPECT_FLOAT_EQ(lo.z, 3 + 2.0f * -1);
    EXPECT_FLOAT_EQ(hi.x, 1 + 0.5f * 5001);
    EXPECT_FLOAT_EQ(hi.y, 2 + 0.25f * 4096);
    EXPECT_FLOAT_EQ(hi.z, 3 + 2.0f * 4096);
    EXPECT_FLOAT_EQ(m.density({1 + 0.5f * 7.5f, 2 + 0.25f * 1, 3 + 2.0f * 2}), 6.0f);  // voxels (7|8, 1, 2) of 5 and 7
}

// Ratio tracking's mean against exp(-sigma_t * density * length): inside the constant block, and
// through all of it, where the density falls linearly to zero over the last voxel (index 7 to 8)
// and the box ends at 8, so the block counts 7.5 voxels.
TEST(NanoVdb, TransmittanceThroughAConstantBlockIsBeerLambert) {
    const NanoVdbMedium m = blockMedium();
    Pcg32 rng(11);
    struct Case {
        Vec3f o;
        float length, expectedDepth;  // world units; density times length
    };
    const float y = 0.25f * 3.5f, z = 5 + 0.25f * 3.5f;
    const Case cases[] = {{{1 + 0.25f * 0.5f, y, z}, 1.5f, 0.5f * 1.5f}, {{0, y, z}, 4, 0.5f * 0.25f * 7.5f}};
    for (const Case& c : cases) {
        constexpr int kSamples = 400000;
        Vec3f sum;
        for (int i = 0; i < kSamples; ++i) sum += m.transmittance(c.o, {1, 0, 0}, c.length, rng);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(sum[ch] / kSamples / std::exp(-kVdbSigmaA[ch] * c.expectedDepth), 1.0, 0.01) << "channel " << ch;
    }
    EXPECT_FLOAT_EQ(m.density({1 + 0.25f * 3.5f, y, z - 5}), 0.5f);
    EXPECT_FLOAT_EQ(m.density({1 + 0.25f * 7.5f, y, z - 5}), 0.25f);
}

// Voxels of random density in two leaves with an empty one between (x 8..15), so the majorant
// grid's cells (one per voxel here) differ: ratio tracking (transmittance) and delta tracking (the
// share of paths an absorber lets through) along an oblique ray against exp(-sigma_t * the
// density's integral), by the midpoint rule over the grid's own lookups. A cell's majorant below
// the density it covers biases both: the density rises from voxel 15 (empty) to voxel 16 in cells
// that only the third leaf's values bound.
TEST(NanoVdb, TrackingThroughVaryingVoxelsMatchesQuadrature) {
    NanoVdbTestGrid g;
    Pcg32 rng(17);
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k)
                if (i < 8 || i >= 16) g.voxels[{i, j, k}] = 0.5f + 0.5f * rng.uniform();
    const float sigma = 0.1f;
    const NanoVdbMedium m(readBack(test::nanoVdbFile({g})), {sigma, sigma, sigma}, {}, Transform{}, HenyeyGreenstein(0));
    const Vec3f o{-1, 1.5f, 2.5f}, d = normalize(Vec3f{26, 4, 3});
    const float length = 27;
    const double depth = sigma * test::midpointDepth(o, d, length, 20000, {0, 0, 0}, {24, 8, 8}, [&](Vec3f p) { return m.density(p); });
    ASSERT_GT(depth, 1.0);  // thick enough to matter, thin enough for a tight estimate
    constexpr int kSamples = 200000;
    double transmitted = 0, passed = 0;
    for (int i = 0; i < kSamples; ++i) {
        transmitted += m.transmittance(o, d, length, rng).x;
        passed += !isBlack(m.sample(o, d, length, 0, rng).weight);
    }
    EXPECT_NEAR(transmitted / kSamples / std::exp(-depth), 1.0, 0.01);
    EXPECT_NEAR(passed / kSamples / std::exp(-depth), 1.0, 0.02);
}

// One dense voxel among thin ones in a leaf, and a second leaf of thin voxels: the majorant of
// every cell bounds the interpolated density at 300,000 random points (on and between voxel
// centres), and cells two voxels away from the dense voxel stay below it (voxels bounded one by
// one, not by their leaf's largest value).
TEST(NanoVdb, MajorantsBoundTheDensityVoxelByVoxel) {
    NanoVdbTestGrid g;
    Pcg32 rng(23);
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k) g.voxels[{i, j, k}] = 0.1f * rng.uniform();
    g.voxels[{2, 5, 6}] = 4;
    const NanoVdbGrid read = readBack(test::nanoVdbFile({g}));
    const float sigmaT = 1.5f;
    const MajorantGrid m = nanoVdbMajorants(read, sigmaT);
    ASSERT_EQ(m.nx, 16);
    ASSERT_EQ(m.ny, 8);
    ASSERT_EQ(m.nz, 8);
    for (int n = 0; n < 300000; ++n) {
        const float x = 16 * rng.uniform(), y = 8 * rng.uniform(), z = 8 * rng.uniform();
        ASSERT_LE(sigmaT * read.interpolate(x, y, z), m.at(int(x), int(y), int(z)) * (1 + 1e-6f)) << x << " " << y << " " << z;
    }
    // Voxel centres sit at integers and voxel i spans [i, i + 1): the dense voxel reaches cells
    // 1..3, 4..6, 5..7 by interpolation, one voxel beyond that for safety.
    for (int x = 0; x < 16; ++x)
        for (int y = 0; y < 8; ++y)
            for (int z = 0; z < 8; ++z) {
                const bool near = std::abs(x - 2) <= 2 && std::abs(y - 5) <= 2 && std::abs(z - 6) <= 2;
                if (!near) {
                    EXPECT_LE(m.at(x, y, z), sigmaT * 0.1f) << x << " " << y << " " << z;
                }
            }
}

TEST(NanoVdb, UnsupportedFilesAreErrorsNamingTheFile) {
    const std::string good = test::nanoVdbFile({blockGrid()});
    const auto errorContains = [](const std::string& bytes, const std::string& text) {
        const std::string e = vdbErrorOf(bytes);
        EXPECT_EQ(e.rfind("t.nvdb: ", 0), 0u) << e;
        EXPECT_NE(e.find(text), std::string::npos) << e;
    };
    std::string notNano = good;
    notNano[0] = 'X';
    errorContains(notNano, "not a NanoVDB file");
    errorContains(test::nanoVdbFile({blockGrid()}, 0, (29u << 21) | (3u << 10)), "version 29.3.0 is not supported");
    errorContains(test::nanoVdbFile({blockGrid()}, 1), "compressed with ZIP");
    errorContains(test::nanoVdbFile({blockGrid()}, 2), "compressed with Blosc");
    NanoVdbTestGrid doubles = blockGrid();
    doubles.type = 2;
    errorContains(test::nanoVdbFile({doubles}), "NanoVDB type 2, not float");
    NanoVdbTestGrid levelSet = blockGrid();
    levelSet.gridClass = 1;
    errorContains(test::nanoVdbFile({levelSet}), "not a fog volume");
    NanoVdbTestGrid nan = blockGrid();
    nan.voxels[{20, 0, 0}] = NAN;
    errorContains(test::nanoVdbFile({nan}), "non-finite value");
    errorContains("", "empty file");
    errorContains(good.substr(0, good.size() - 1), "truncated");
    // The tree's root offset pointing past the buffer's end.
    std::string rootFar = good;
    const int64_t far = int64_t(1) << 40;
    std::memcpy(&rootFar[200 + 672 + 24], &far, 8);
    errorContains(rootFar, "the root node");
    // Another grid name: not an error, no grid.
    std::istringstream in(good);
    EXPECT_FALSE(readNanoVdbGrid(in, "temperature", "t.nvdb"));
}

// Every truncation fails with an error naming the file; bytes flipped anywhere (and often in the
// headers, tree and node masks) either still read or fail that way, and what reads looks up finite
// values. Under a sanitizer build this is also the memory-safety check.
TEST(NanoVdb, TruncatedAndCorruptedFilesNeverCrash) {
    NanoVdbTestGrid g = spreadGrid();  // less what lies outside the first root tile: a smaller file
    g.tiles.pop_back();
    g.voxels.erase({-1, -1, -1});
    g.voxels.erase({5000, 0, 0});
    const std::string good = test::nanoVdbFile({g});
    for (std::size_t n = 0; n < good.size(); n += n < 2000 ? 1 : 4999) {
        const std::string e = vdbErrorOf(good.substr(0, n));
        ASSERT_EQ(e.rfind("t.nvdb: ", 0), 0u) << "length " << n << ": " << e;
    }
    Pcg32 rng(5);
    int accepted = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        std::string bad = good;
        const std::size_t span = trial % 2 ? bad.size() : 1200;  // half within the headers, the grid and the root
        for (int flips = 1 + trial % 3; flips > 0; --flips)
            bad[std::size_t(rng.uniform() * span) % bad.size()] ^= char(1 + int(rng.uniform() * 255));
        std::istringstream in(bad);
        try {
            const std::optional<NanoVdbGrid> read = readNanoVdbGrid(in, "density", "t.nvdb");
            if (!read) continue;
            ++accepted;
            for (int i = 0; i < 20; ++i) {
                const float v = read->interpolate(-10 + 150 * rng.uniform(), -5 + 20 * rng.uniform(), -5 + 20 * rng.uniform());
                ASSERT_TRUE(std::isfinite(v));
            }
        } catch (const NanoVdbError& e) {
            ASSERT_EQ(std::string(e.what()).rfind("t.nvdb: ", 0), 0u) << e.what();
        }
    }
    EXPECT_GT(accepted, 50);  // flips in voxel values mostly read
}

std::string mediumScene(const test::TempDir& dir, const std::string& params) {
    return dir.write("s.pbrt", "LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                               "MakeNamedMedium \"m\" \"string type\" \"nanovdb\" " + params + "\n");
}

TEST(NanoVdb, SceneReadsTheMediumAndNamesItsErrors) {
    test::TempDir dir;
    dir.write("block.nvdb", test::nanoVdbFile({blockGrid()}));
    EXPECT_TRUE(parseSceneFile(mediumScene(dir, "\"string filename\" \"block.nvdb\" \"float g\" 0.5")).warnings.empty());
    const auto errorContains = [&](const std::string& params, const std::string& text) {
        const std::string e = test::sceneErrorOf(mediumScene(dir, params));
        EXPECT_NE(e.find("s.pbrt:4: MakeNamedMedium \"m\": "), std::string::npos) << e;
        EXPECT_NE(e.find(text), std::string::npos) << e;
    };
    errorContains("", "needs \"string filename\"");
    errorContains("\"string filename\" \"block.nvdb\" \"string gridname\" \"smoke\"", "block.nvdb: no grid named \"smoke\"");
    const std::string file = test::nanoVdbFile({blockGrid()});
    dir.write("cut.nvdb", file.substr(0, 5000));
    errorContains("\"string filename\" \"cut.nvdb\"", "cut.nvdb: truncated");
    NanoVdbTestGrid temperature = blockGrid();
    temperature.name = "temperature";
    dir.write("fire.nvdb", test::nanoVdbFile({blockGrid(), temperature}));
    errorContains("\"string filename\" \"fire.nvdb\"", "fire.nvdb: grid \"temperature\" makes the medium emit");
    EXPECT_NO_THROW(parseSceneFile(mediumScene(dir, "\"string filename\" \"fire.nvdb\" \"float Lescale\" 0")));
}

}  // namespace
}  // namespace lenslab
