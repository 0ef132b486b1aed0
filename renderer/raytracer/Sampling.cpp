#include "Sampling.h"

#include <array>

namespace lenslab {

namespace {

// Direction numbers from primitive polynomials (Joe & Kuo): dimension 0 is the van der Corput
// sequence; 1: x + 1; 2: x^2 + x + 1, m = 1, 3; 3: x^3 + x + 1, m = 1, 3, 1.
std::array<std::array<std::uint32_t, 32>, 4> makeDirections() {
    std::array<std::array<std::uint32_t, 32>, 4> v{};
    struct Poly {
        int degree;
        std::uint32_t a;
        std::array<std::uint32_t, 3> m;
    };
    const Poly polys[3] = {{1, 0, {1, 0, 0}}, {2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}};
    for (int k = 0; k < 32; ++k) v[0][k] = 1u << (31 - k);
    for (int d = 1; d < 4; ++d) {
        const Poly& p = polys[d - 1];
        const int s = p.degree;
        for (int k = 0; k < 32; ++k) {
            if (k < s) {
                v[d][k] = p.m[k] << (31 - k);
                continue;
            }
            std::uint32_t x = v[d][k - s] ^ (v[d][k - s] >> s);
            for (int i = 1; i < s; ++i)
                if ((p.a >> (s - 1 - i)) & 1u) x ^= v[d][k - i];
            v[d][k] = x;
        }
    }
    return v;
}

const auto kDirections = makeDirections();

}  // namespace

float sobolSample(std::uint32_t index, int dimension, std::uint32_t scramble) {
    std::uint32_t x = scramble;
    for (int k = 0; index != 0; ++k, index >>= 1)
        if (index & 1u) x ^= kDirections[dimension][k];
    return std::min(float(x >> 8) * 0x1p-24f, 0x1.fffffep-1f);
}

}  // namespace lenslab
