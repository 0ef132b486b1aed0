#include "ImageDifference.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace lenslab {

namespace {

void requireSameSize(const RgbaImage& a, const RgbaImage& b) {
    if (a.width != b.width || a.height != b.height)
        throw PngError("images of different sizes: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                       " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
}

}  // namespace

double rmsDifference(const RgbaImage& a, const RgbaImage& b) {
    requireSameSize(a, b);
    const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
    if (pixels == 0) return 0;
    double sum = 0;
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.rgba[4 * p + c]) - double(b.rgba[4 * p + c]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * pixels));
}

RgbaImage differenceImage(const RgbaImage& a, const RgbaImage& b, double gain) {
    requireSameSize(a, b);
    RgbaImage out{a.width, a.height, std::vector<std::uint8_t>(a.rgba.size())};
    for (std::size_t p = 0; p < a.rgba.size() / 4; ++p) {
        int largest = 0;
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(a.rgba[4 * p + c]) - int(b.rgba[4 * p + c])));
        const auto shade = static_cast<std::uint8_t>(255 - std::min(255.0, std::round(largest * gain)));
        out.rgba[4 * p] = out.rgba[4 * p + 1] = out.rgba[4 * p + 2] = shade;
        out.rgba[4 * p + 3] = 255;
    }
    return out;
}

}  // namespace lenslab
