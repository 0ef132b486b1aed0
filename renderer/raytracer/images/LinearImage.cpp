#include "images/LinearImage.h"

#include <algorithm>
#include <cmath>

#include "images/RgbImageFile.h"

namespace lenslab {

namespace {

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
    RgbImageFile file = readRgbImageFile(path, name, where);
    if (std::int64_t(file.width) * file.height > (1LL << 26)) sceneFail(where, "image '" + name + "' is too large");
    LinearImage image;
    image.width = file.width;
    image.height = file.height;
    image.texels = std::move(file.rgb);
    for (Vec3f& c : image.texels) {
        if (file.integerFormat) c = {srgbDecode(c.x), srgbDecode(c.y), srgbDecode(c.z)};
        c = {usable(c.x), usable(c.y), usable(c.z)};
    }
    return image;
}

}  // namespace lenslab
