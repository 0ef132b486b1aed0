#include "sampling/Noise.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace lenslab {

namespace {

// The permutation of 0..255 published with Perlin's reference implementation of improved noise
// (https://mrl.cs.nyu.edu/~perlin/noise/); pbrt-v3 uses the same table, so lenslab's noise
// textures match its pictures.
constexpr std::uint8_t kPermutation[256] = {
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69, 142,
    8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219, 203, 117,
    35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175, 74, 165, 71,
    134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230, 220, 105, 92, 41,
    55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76, 132, 187, 208, 89,
    18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173, 186, 3, 64, 52, 217, 226,
    250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206, 59, 227, 47, 16, 58, 17, 182,
    189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163, 70, 221, 153, 101, 155, 167, 43,
    172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232, 178, 185, 112, 104, 218, 246, 97,
    228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162, 241, 81, 51, 145, 235, 249, 14, 239, 107,
    49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204, 176, 115, 121, 50, 45, 127, 4, 150, 254, 138,
    236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141, 128, 195, 78, 66, 215, 61, 156, 180
};

int permute(int i) { return kPermutation[i & 255]; }

// The gradient direction that hash h (0..15) of a lattice corner chooses: +-a +-b of two axes, the
// signs by the hash's low bits; the choice of axes per hash is pbrt-v3's (it differs from Perlin's
// code for hashes 12 to 15), so that the patterns come out as in pbrt-v3. As a table: the hashes
// are random, and the branches of choosing would be mispredicted half the time.
struct Direction {
    float x, y, z;
};
constexpr Direction direction(int h) {
    const bool pair = h == 12 || h == 13;
    const bool aIsX = h < 8 || pair, bIsY = h < 4 || pair;
    const float a = (h & 1) ? -1 : 1, b = (h & 2) ? -1 : 1;
    return {aIsX ? a : 0, aIsX ? (bIsY ? b : 0) : a, bIsY ? 0 : b};
}
constexpr std::array<Direction, 16> kDirections = [] {
    std::array<Direction, 16> table{};
    for (int h = 0; h < 16; ++h) table[h] = direction(h);
    return table;
}();

// The dot product of the offset (dx, dy, dz) with hash h's direction: with one component zero, the
// same sum of two signed offsets, bit for bit, that choosing them would give.
float gradient(int h, float dx, float dy, float dz) {
    const Direction& g = kDirections[h];
    return g.x * dx + g.y * dy + g.z * dz;
}

// 6t^5 - 15t^4 + 10t^3: continuous second derivative across cells.
float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

float lerp(float t, float a, float b) { return a + t * (b - a); }

// From 2^24 on every float is an integer, a lattice point where the noise is zero; this also
// keeps NaN and infinities out of the integer conversions below.
bool onTheLattice(Vec3f p) {
    constexpr float kAllIntegers = 16777216.0f;
    return !(std::fabs(p.x) < kAllIntegers && std::fabs(p.y) < kAllIntegers && std::fabs(p.z) < kAllIntegers);
}

// The lattice cell around a point: its lower corner and the gradient hashes of its eight corners,
// corner (i, j, k) at i + 2j + 4k, each the hash of Perlin's nested permutations of x+i, y+j, z+k.
struct Cell {
    float x, y, z;  // the lower corner
    int hash[8];
};

Cell cellAround(Vec3f p) {
    Cell c{std::floor(p.x), std::floor(p.y), std::floor(p.z), {}};
    const int x = int(c.x) & 255, y = int(c.y) & 255, z = int(c.z) & 255;  // the lattice repeats every 256 cells
    const int a = permute(x) + y, b = permute(x + 1) + y;
    const int corners[4] = {permute(a) + z, permute(b) + z, permute(a + 1) + z, permute(b + 1) + z};  // by i + 2j
    for (int ij = 0; ij < 4; ++ij) {
        c.hash[ij] = permute(corners[ij]) & 15;
        c.hash[ij + 4] = permute(corners[ij] + 1) & 15;
    }
    return c;
}

// The noise at offset (dx, dy, dz) from the cell's lower corner.
float noiseIn(const Cell& c, float dx, float dy, float dz) {
    const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    const auto corner = [&](int i, int j, int k) { return gradient(c.hash[i + 2 * j + 4 * k], dx - i, dy - j, dz - k); };
    const float y0 = lerp(wy, lerp(wx, corner(0, 0, 0), corner(1, 0, 0)), lerp(wx, corner(0, 1, 0), corner(1, 1, 0)));
    const float y1 = lerp(wy, lerp(wx, corner(0, 0, 1), corner(1, 0, 1)), lerp(wx, corner(0, 1, 1), corner(1, 1, 1)));
    return lerp(wz, y0, y1);
}

}  // namespace

float perlinNoise(Vec3f p) {
    if (onTheLattice(p)) return 0;
    const Cell c = cellAround(p);
    return noiseIn(c, p.x - c.x, p.y - c.y, p.z - c.z);
}

// The three nearby points nearly always share p's cell, and with it its hashes: only the offsets
// differ (the same arithmetic as perlinNoise at each point, so the same values).
Vec3f perlinNoiseGradient(Vec3f p) {
    constexpr float kDelta = 0.01f;
    if (onTheLattice(p))
        return Vec3f{perlinNoise(p + Vec3f{kDelta, 0, 0}), perlinNoise(p + Vec3f{0, kDelta, 0}),
                     perlinNoise(p + Vec3f{0, 0, kDelta})} / kDelta;
    const Cell c = cellAround(p);
    const float dx = p.x - c.x, dy = p.y - c.y, dz = p.z - c.z;
    const float n = noiseIn(c, dx, dy, dz);
    const Vec3f q = p + Vec3f{kDelta, kDelta, kDelta};
    const float nx = std::floor(q.x) == c.x ? noiseIn(c, q.x - c.x, dy, dz) : perlinNoise({q.x, p.y, p.z});
    const float ny = std::floor(q.y) == c.y ? noiseIn(c, dx, q.y - c.y, dz) : perlinNoise({p.x, q.y, p.z});
    const float nz = std::floor(q.z) == c.z ? noiseIn(c, dx, dy, q.z - c.z) : perlinNoise({p.x, p.y, q.z});
    return Vec3f{nx - n, ny - n, nz - n} / kDelta;
}

float fractionalBrownianMotion(Vec3f p, float omega, int octaves) {
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * perlinNoise(frequency * p);
        frequency *= 1.99f;  // not 2: octaves' lattices do not line up
        amplitude *= omega;
    }
    return sum;
}

float turbulence(Vec3f p, float omega, int octaves) {
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * std::fabs(perlinNoise(frequency * p));
        frequency *= 1.99f;
        amplitude *= omega;
    }
    return sum + 0.2f * amplitude;
}

}  // namespace lenslab
