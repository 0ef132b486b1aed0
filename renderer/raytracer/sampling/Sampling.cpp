#include "sampling/Sampling.h"

#include <algorithm>
#include <array>

namespace lenslab {

namespace {

constexpr int kDigits = 16;  // base-4 digits in 32 bits

// GF(4) = {0, 1, a, a + 1} with a^2 = a + 1, elements as 2-bit numbers (addition is xor).
constexpr std::uint8_t kMul[4][4] = {{0, 0, 0, 0}, {0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}};

// The lens's two dimensions are Faure's over GF(4) at the elements a and a + 1: the Pascal matrix
// with entries C(c, r) e^(c - r). kLensTerms[l][c][d] is what index digit c = d adds (xor) to lens
// dimension l's bits, output digit r sitting at bits 31-2r and 30-2r. With the film's two Sobol'
// dimensions these fill every 4^k x 4^k grid cell pair by pair at 16^k samples (the Faure pairs as
// parts of a (0, 4)-sequence in base 4; film against lens checked in tests/renderer/test_sampler.cpp).
using Terms = std::array<std::array<std::array<std::uint32_t, 4>, kDigits>, 2>;

Terms makeLensTerms() {
    std::array<std::array<std::uint8_t, kDigits>, kDigits> pascal{};  // C(c, r) mod 2
    for (int c = 0; c < kDigits; ++c)
        for (int r = 0; r <= c; ++r) pascal[c][r] = r == 0 || r == c || (pascal[c - 1][r - 1] ^ pascal[c - 1][r]);
    Terms t{};
    for (int l = 0; l < 2; ++l) {
        const std::uint8_t e = std::uint8_t(2 + l);
        for (int c = 0; c < kDigits; ++c)
            for (int d = 0; d < 4; ++d) {
                std::uint32_t bits = 0;
                std::uint8_t power = 1;  // e^(c - r), r running down from c
                for (int r = c; r >= 0; --r, power = kMul[power][e])
                    bits ^= std::uint32_t(kMul[pascal[c][r] ? power : 0][d]) << (30 - 2 * r);
                t[l][c][d] = bits;
            }
    }
    return t;
}

// Sobol's second dimension (primitive polynomial x + 1): the Pascal matrix over GF(2).
std::array<std::uint32_t, 32> makeFilmYDirections() {
    std::array<std::uint32_t, 32> v{};
    v[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    return v;
}

const Terms kLensTerms = makeLensTerms();
const auto kFilmYDirections = makeFilmYDirections();

// The lens's index digits are relabelled so that samples 0 and 1 (and 2 and 3) of each group of
// four fall in opposite halves of both lens dimensions, as the film's do: 2 spp is stratified too.
// A permutation within the groups keeps every net property.
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
    for (int k = 0; k < 8; ++k) seeds_[k] = std::uint32_t(mix64(pixelSeed + k));
}

PixelSample PixelSampler::operator()(std::uint32_t index) const {
    std::uint32_t filmY = 0, lensU = 0, lensV = 0;
    for (int k = 0; k < 32 && (index >> k) != 0; ++k)
        if ((index >> k) & 1u) filmY ^= kFilmYDirections[k];
    for (int c = 0; c < kDigits && (index >> (2 * c)) != 0; ++c) {
        const std::uint8_t d = kRelabel[(index >> (2 * c)) & 3u];
        lensU ^= kLensTerms[0][c][d];
        lensV ^= kLensTerms[1][c][d];
    }
    return {unitFloat(owenScramble(reverseBits(index), seeds_[0])), unitFloat(owenScramble(filmY, seeds_[1])),
            unitFloat(owenScramble(lensU, seeds_[2])), unitFloat(owenScramble(lensV, seeds_[3])),
            unitFloat(owenScramble(reverseBits(owenScramble(index, seeds_[5])), seeds_[4])),
            unitFloat(owenScramble(reverseBits(owenScramble(index, seeds_[7])), seeds_[6]))};
}

}  // namespace lenslab
