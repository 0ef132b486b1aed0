#include "Sampling.h"

#include <algorithm>
#include <array>

namespace lenslab {

namespace {

constexpr int kDigits = 16;  // base-4 digits in 32 bits

// GF(4) = {0, 1, a, a + 1} with a^2 = a + 1, elements as 2-bit numbers (addition is xor).
constexpr std::uint8_t kMul[4][4] = {{0, 0, 0, 0}, {0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}};

// Faure's generator of dimension j is the Pascal matrix at the field element j: entry (r, c) is
// C(c, r) j^(c - r). kTerms[j][c][d] is what index digit c = d adds (xor) to dimension j's bits,
// output digit r sitting at bits 31-2r and 30-2r.
using Terms = std::array<std::array<std::array<std::uint32_t, 4>, kDigits>, 4>;

Terms makeTerms() {
    Terms t{};
    for (int j = 0; j < 4; ++j) {
        std::array<std::array<std::uint8_t, kDigits>, kDigits> pascal{};  // C(c, r) mod 2 times j^(c-r)
        for (int c = 0; c < kDigits; ++c)
            for (int r = 0; r <= c; ++r) pascal[c][r] = r == 0 || r == c || (pascal[c - 1][r - 1] ^ pascal[c - 1][r]);
        for (int c = 0; c < kDigits; ++c)
            for (int d = 0; d < 4; ++d) {
                std::uint32_t bits = 0;
                std::uint8_t power = 1;  // j^(c - r), r running down from c
                for (int r = c; r >= 0; --r, power = kMul[power][j]) {
                    const std::uint8_t g = pascal[c][r] ? power : 0;
                    bits ^= std::uint32_t(kMul[g][d]) << (30 - 2 * r);
                }
                t[j][c][d] = bits;
            }
    }
    return t;
}

const Terms kTerms = makeTerms();

// Index digits relabelled so that samples 0 and 1 (and 2 and 3) of each group of four fall in
// opposite halves of every dimension: 2 spp is stratified too. A permutation within the groups
// keeps every net property.
constexpr std::uint8_t kRelabel[4] = {0, 2, 1, 3};

std::uint32_t reverseBits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

// A nested (Owen) scramble by hashing: with the bits reversed, each step changes a bit only as a
// function of the seed and of the bits below it (the leading bits of the number), so every dyadic
// interval maps onto one of the same size and stratification survives.
std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
    x = reverseBits(x);
    x += seed;
    x ^= x * 0xc13da58au;
    x *= (seed >> 15) | 1u;
    x ^= x * 0x9362da5cu;
    x += seed ^ (seed >> 11);
    x ^= x * 0xe5c15b62u;
    return reverseBits(x);
}

float unitFloat(std::uint32_t bits) { return std::min(float(bits >> 8) * 0x1p-24f, 0x1.fffffep-1f); }

}  // namespace

PixelSampler::PixelSampler(std::uint64_t pixelSeed) {
    for (int k = 0; k < 4; ++k) seeds_[k] = std::uint32_t(mix64(pixelSeed + k));
}

PixelSample PixelSampler::operator()(std::uint32_t index) const {
    std::uint32_t bits[4] = {0, 0, 0, 0};
    for (int c = 0; index != 0; ++c, index >>= 2) {
        const std::uint8_t d = kRelabel[index & 3u];
        for (int j = 0; j < 4; ++j) bits[j] ^= kTerms[j][c][d];
    }
    return {unitFloat(owenScramble(bits[0], seeds_[0])), unitFloat(owenScramble(bits[1], seeds_[1])),
            unitFloat(owenScramble(bits[2], seeds_[2])), unitFloat(owenScramble(bits[3], seeds_[3]))};
}

}  // namespace lenslab
