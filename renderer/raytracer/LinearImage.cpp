#include "LinearImage.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// Negative or non-finite texels would make radiance and sampling densities meaningless.
float usable(float v) { return std::isfinite(v) && v > 0 ? v : 0.0f; }

bool isIntegerFormat(OIIO::TypeDesc t) {
    return t.basetype != OIIO::TypeDesc::FLOAT && t.basetype != OIIO::TypeDesc::HALF &&
           t.basetype != OIIO::TypeDesc::DOUBLE;
}

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
    auto in = OIIO::ImageInput::open(path);
    if (!in) sceneFail(where, "cannot read image '" + name + "' (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width < 1 || spec.height < 1 || channels < 1 || std::int64_t(spec.width) * spec.height > (1LL << 26))
        sceneFail(where, "image '" + name + "' has no pixels or is too large");
    std::vector<float> raw(std::size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data()))
        sceneFail(where, "cannot read the pixels of image '" + name + "' (" + in->geterror() + ")");
    const bool srgb = isIntegerFormat(spec.format);
    LinearImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.texels.resize(std::size_t(spec.width) * spec.height);
    for (std::size_t i = 0; i < image.texels.size(); ++i) {
        const float* p = &raw[i * channels];
        Vec3f c = channels >= 3 ? Vec3f{p[0], p[1], p[2]} : Vec3f{p[0], p[0], p[0]};
        if (srgb) c = {srgbDecode(c.x), srgbDecode(c.y), srgbDecode(c.z)};
        image.texels[i] = {usable(c.x), usable(c.y), usable(c.z)};
    }
    return image;
}

}  // namespace lenslab
