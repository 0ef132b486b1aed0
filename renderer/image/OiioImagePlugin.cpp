// The OpenImageIO side of ImageFileReader: a module loaded on the first image read.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstring>

#include "ImagePluginAbi.h"

namespace {

constexpr long long kMaxPixels = 1LL << 28;

int fail(char* error, std::size_t size, const std::string& message) {
    std::snprintf(error, size, "%s", message.c_str());
    return 1;
}

}  // namespace

extern "C" int lenslab_read_image(const char* path, PluginImage* out, char* error, std::size_t errorSize) {
    // Colours as stored, not multiplied by alpha (OpenImageIO premultiplies PNG by default; pbrt
    // ignores alpha).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) return fail(error, errorSize, OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || (long long)spec.width * spec.height > kMaxPixels)
        return fail(error, errorSize, "no pixels, or more than 268 Mpixels");
    const std::size_t count = std::size_t(spec.width) * spec.height * spec.nchannels;
    float* pixels = new (std::nothrow) float[count];
    if (!pixels) return fail(error, errorSize, "out of memory");
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels)) {
        delete[] pixels;
        return fail(error, errorSize, in->geterror());
    }
    const auto base = spec.format.basetype;
    out->width = spec.width;
    out->height = spec.height;
    out->channels = spec.nchannels;
    out->floatingPoint = base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE;
    out->eightBit = base == OIIO::TypeDesc::UINT8;
    out->pixels = pixels;
    return 0;
}

extern "C" void lenslab_free_image(PluginImage* image) {
    delete[] image->pixels;
    image->pixels = nullptr;
}
