#include "images/RgbImageFile.h"

#include <cmath>
#include <stdexcept>

#include "ImageFileReader.h"

namespace lenslab {

float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

RgbImageFile readRgbImageFile(const std::string& path, const std::string& name, const SourceLocation& where) {
    DecodedImage raw;
    try {
        raw = readImageFile(path);
    } catch (const std::runtime_error& e) {
        sceneFail(where, "cannot read image '" + name + "' (" + e.what() + ")");
    }
    const int channels = raw.channels;
    RgbImageFile image;
    image.width = raw.width;
    image.height = raw.height;
    image.integerFormat = !raw.floatingPoint;
    image.eightBit = raw.eightBit;
    image.rgb.resize(std::size_t(raw.width) * raw.height);
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const float* p = &raw.pixels[i * channels];
        image.rgb[i] = channels >= 3 ? Vec3f{p[0], p[1], p[2]} : Vec3f{p[0], p[0], p[0]};  // grey (+ alpha)
    }
    return image;
}

}  // namespace lenslab
