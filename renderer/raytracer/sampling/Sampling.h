#pragma once
// Random numbers and warps. Every sample is a pure function of (seed, pixel, sample index,
// dimension), so the image does not depend on how tiles are scheduled across threads.
#include <cmath>
#include <cstdint>

#include "core/Vec3f.h"

namespace lenslab {

inline std::uint64_t mix64(std::uint64_t z) {  // splitmix64 finaliser
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline std::uint64_t hashCombine(std::uint64_t a, std::uint64_t b) { return mix64(a ^ mix64(b)); }

// PCG32 (O'Neill 2014): small state, good statistics.
class Pcg32 {
public:
    explicit Pcg32(std::uint64_t seed, std::uint64_t stream = 1) : inc_((stream << 1u) | 1u) {
        next();
        state_ += seed;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const std::uint32_t xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const std::uint32_t rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
    }
    float uniform() { return std::min(float(next() >> 8) * 0x1p-24f, 0x1.fffffep-1f); }
    // A distance of exponential density exp(-t) (in mean free paths). 1 - u is exact for uniform()'s
    // multiples of 2^-24, so logf serves where log1pf would cost twice the time.
    float exponential() { return -std::log(1 - uniform()); }

private:
    std::uint64_t state_ = 0, inc_;
};

// The camera dimensions of one pixel sample: where it falls in the pixel and on the lens, and when
// in the shutter interval.
struct PixelSample {
    float filmX, filmY, lensU, lensV, time;  // [0, 1)
    // A sixth dimension for the spectral film's wavelength, padded like the time (a van der Corput
    // sequence over a per-pixel shuffle of the index): stratified on its own, independent of the others.
    float wavelength;
};

// A pixel's camera samples, each dimension Owen-scrambled with its own seed drawn from the pixel's
// (scrambles differ per pixel, so no pattern repeats across the image). The film takes Sobol's
// first two dimensions, a (0, 2)-sequence: any 2^k samples fill every 2^a x 2^b cell of the pixel
// with a + b = k. The lens takes the generalised Faure dimensions of base 4 that complete them to
// a 4D sequence stratified pair by pair: every pair of dimensions (film x/y, lens u/v, film against
// lens) fills each cell of a 4 x 4 grid with 16 samples, of a 16 x 16 grid with 256. The lens
// samples are thus spread over the pupil independently of where the film samples fall. The time is
// a fifth dimension no base-2 or base-4 net can stratify against all four: a time stratified at
// every power of two has its quarter fixed by the sample index mod 4, as the lens's is. So it is
// padded, as pbrt-v4 pads: van der Corput over the index shuffled per pixel by a nested permutation
// (each aligned block of 2^k indices onto another), then Owen-scrambled. Any aligned 2^k samples
// still fall one in each 1/2^k of the shutter interval, and the pairing with film and lens is
// random (tests/renderer/test_sampler.cpp).
class PixelSampler {
public:
    explicit PixelSampler(std::uint64_t pixelSeed);
    PixelSample operator()(std::uint32_t index) const;

private:
    std::uint32_t seeds_[8];  // film x, film y, lens u, lens v, time, time's index shuffle, wavelength, its shuffle
};

inline Vec3f cosineHemisphere(float u1, float u2) {
    const float r = std::sqrt(u1), phi = 2.0f * float(M_PI) * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u1))};
}

inline Vec3f uniformSphere(float u1, float u2) {
    const float z = 1.0f - 2.0f * u1, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * float(M_PI) * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Shirley-Chiu concentric map of the unit square to the unit disc (keeps stratification).
inline void concentricDisk(float u1, float u2, float& x, float& y) {
    const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
    if (a == 0 && b == 0) {
        x = y = 0;
        return;
    }
    float r, theta;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        theta = float(M_PI) / 4 * (b / a);
    } else {
        r = b;
        theta = float(M_PI) / 2 - float(M_PI) / 4 * (a / b);
    }
    x = r * std::cos(theta);
    y = r * std::sin(theta);
}

inline float powerHeuristic(float pa, float pb) {
    const float a = pa * pa, b = pb * pb;
    return a + b > 0 ? a / (a + b) : 0.0f;
}

}  // namespace lenslab
