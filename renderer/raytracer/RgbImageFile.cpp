#include "RgbImageFile.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace lenslab {

float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

RgbImageFile readRgbImageFile(const std::string& path, const std::string& name, const SourceLocation& where) {
    // Colours as stored, not multiplied by alpha (OpenImageIO premultiplies PNG by default; pbrt
    // ignores alpha).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) sceneFail(where, "cannot read image '" + name + "' (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width < 1 || spec.height < 1 || channels < 1 || std::int64_t(spec.width) * spec.height > (1LL << 28))
        sceneFail(where, "image '" + name + "' has no pixels or is too large");
    std::vector<float> raw(std::size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data()))
        sceneFail(where, "cannot read the pixels of image '" + name + "' (" + in->geterror() + ")");
    const auto base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
    RgbImageFile image;
    image.width = spec.width;
    image.height = spec.height;
    image.integerFormat = base != OIIO::TypeDesc::FLOAT && base != OIIO::TypeDesc::HALF && base != OIIO::TypeDesc::DOUBLE;
    image.eightBit = base == OIIO::TypeDesc::UINT8;
    image.rgb.resize(std::size_t(spec.width) * spec.height);
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const float* p = &raw[i * channels];
        image.rgb[i] = channels >= 3 ? Vec3f{p[0], p[1], p[2]} : Vec3f{p[0], p[0], p[0]};  // grey (+ alpha)
    }
    return image;
}

}  // namespace lenslab
