#include "FieldSamples.h"

#include <algorithm>
#include <random>

namespace lenslab::tradeoff {

void fieldRasterPosition(double field, int width, int height, double& rasterX, double& rasterY) {
    // Half a pixel inside the frame, so jittered samples stay on the film.
    rasterX = std::clamp(0.5 * width * (1 + field), 0.5, width - 0.5);
    rasterY = std::clamp(0.5 * height * (1 - field), 0.5, height - 0.5);
}

std::vector<CameraSample> fieldSamples(double field, int width, int height, int count) {
    double x, y;
    fieldRasterPosition(field, width, height, x, y);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<CameraSample> samples(count);
    for (CameraSample& s : samples) s = {x + u(rng) - 0.5, y + u(rng) - 0.5, u(rng), u(rng)};
    return samples;
}

}  // namespace lenslab::tradeoff
