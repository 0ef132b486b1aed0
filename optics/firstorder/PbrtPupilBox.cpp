#include "firstorder/PbrtPupilBox.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "trace/RayBatch.h"

namespace lenslab {

namespace {

constexpr unsigned kSamples = 1024 * 1024;  // pbrt-v3's sample count: its box is where they fall
constexpr int kPbrtRadii = 64;              // pbrt-v3's boxes per half-diagonal
constexpr unsigned kChunk = 4096;           // rays traced together

// The radical inverse of i in base 2 (bits mirrored) and in base 3: pbrt-v3's first two Halton
// dimensions.
double radicalInverse2(unsigned i) {
    double inverse = 0, digit = 0.5;
    for (; i > 0; i >>= 1, digit *= 0.5) inverse += (i & 1) * digit;
    return inverse;
}

double radicalInverse3(unsigned i) {
    double inverse = 0, digit = 1.0 / 3;
    for (; i > 0; i /= 3, digit /= 3) inverse += (i % 3) * digit;
    return inverse;
}

}  // namespace

// Sample i pairs the film point (i + 0.5) / n along the segment with the i-th Halton point on the
// rear vertex's plane; the box is where the passing points fell, which can fall a fraction of
// their spacing short of the region's true edge: pbrt-v3's exposure is that box's, so it is
// measured the same way.
double pbrtFirstPupilBoxArea(const LensSystem& lens, double filmZ, double filmDiagonalMm) {
    const double half = 1.5 * lens.surfaces.back().apertureRadius;
    const double segment = 0.5 * filmDiagonalMm / kPbrtRadii;
    double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
    RayBatch batch;
    batch.resize(kChunk);
    std::vector<double> xs(kChunk), ys(kChunk);
    for (unsigned first = 0; first < kSamples; first += kChunk) {
        for (unsigned k = 0; k < kChunk; ++k) {
            const unsigned i = first + k;
            const Vec3 film{segment * (i + 0.5) / kSamples, 0, filmZ};
            xs[k] = -half + 2 * half * radicalInverse2(i);
            ys[k] = -half + 2 * half * radicalInverse3(i);
            batch.set(k, {film, normalize(Vec3{xs[k], ys[k], lens.rearZ()} - film)});
        }
        traceBatch(lens, batch, TraceDirection::FilmToScene);
        for (unsigned k = 0; k < kChunk; ++k) {
            if (batch.blocked[k] != BlockReason::None) continue;
            minX = std::min(minX, xs[k]);
            maxX = std::max(maxX, xs[k]);
            minY = std::min(minY, ys[k]);
            maxY = std::max(maxY, ys[k]);
        }
    }
    if (!(minX <= maxX)) return 0;
    // Grown on each side by two sample spacings along the sampled square's diagonal.
    const double grow = 2 * std::sqrt(2.0) * 2 * half / std::sqrt(double(kSamples));
    return (maxX - minX + 2 * grow) * (maxY - minY + 2 * grow);
}

}  // namespace lenslab
