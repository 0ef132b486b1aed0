#include "LinearImage.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ImageFileReader.h"

namespace lenslab {

namespace {

float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// Negative or non-finite texels would make radiance and sampling densities meaningless.
float usable(float v) { return std::isfinite(v) && v > 0 ? v : 0.0f; }

}  // namespace

Vec3f LinearImage::lookup(float s, float t) const {
    const int x = std::clamp(int(s * float(width)), 0, width - 1);
    const int y = std::clamp(int(t * float(height)), 0, height - 1);
    return texels[std::size_t(y) * width + x];
}

Vec3f LinearImage::average() const {
    double r = 0, g = 0, b = 0;
    for (const Vec3f& c : texels) {
        r += c.x;
        g += c.y;
        b += c.z;
    }
    const double n = double(texels.size());
    return {float(r / n), float(g / n), float(b / n)};
}

LinearImage readLinearImage(const std::string& path, const std::string& name, const SourceLocation& where) {
    DecodedImage raw;
    try {
        raw = readImageFile(path);
    } catch (const std::runtime_error& e) {
        sceneFail(where, "cannot read image '" + name + "' (" + e.what() + ")");
    }
    if (std::int64_t(raw.width) * raw.height > (1LL << 26)) sceneFail(where, "image '" + name + "' is too large");
    const int channels = raw.channels;
    LinearImage image;
    image.width = raw.width;
    image.height = raw.height;
    image.texels.resize(std::size_t(raw.width) * raw.height);
    for (std::size_t i = 0; i < image.texels.size(); ++i) {
        const float* p = &raw.pixels[i * channels];
        Vec3f c = channels >= 3 ? Vec3f{p[0], p[1], p[2]} : Vec3f{p[0], p[0], p[0]};
        if (!raw.floatingPoint) c = {srgbDecode(c.x), srgbDecode(c.y), srgbDecode(c.z)};
        image.texels[i] = {usable(c.x), usable(c.y), usable(c.z)};
    }
    return image;
}

}  // namespace lenslab
