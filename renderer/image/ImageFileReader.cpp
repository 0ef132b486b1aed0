#include "ImageFileReader.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "ExrFileReader.h"
#include "ImagePluginAbi.h"
#include "PngCodec.h"

#ifndef LENSLAB_IMAGE_PLUGIN
#error "LENSLAB_IMAGE_PLUGIN (the plugin's path) must be defined by the build"
#endif

namespace lenslab {

namespace {

struct Plugin {
    ReadImageFunction read = nullptr;
    FreeImageFunction release = nullptr;
    std::string error;
};

const Plugin& plugin() {
    static Plugin p;
    static std::once_flag once;
    std::call_once(once, [] {
        void* handle = dlopen(LENSLAB_IMAGE_PLUGIN, RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            p.error = std::string("cannot load the image reader ") + LENSLAB_IMAGE_PLUGIN + ": " + dlerror();
            return;
        }
        p.read = reinterpret_cast<ReadImageFunction>(dlsym(handle, "lenslab_read_image"));
        p.release = reinterpret_cast<FreeImageFunction>(dlsym(handle, "lenslab_free_image"));
        if (!p.read || !p.release) p.error = std::string("the image reader ") + LENSLAB_IMAGE_PLUGIN + " lacks its entry points";
    });
    return p;
}

constexpr std::uint64_t kMaxPixels = 1ULL << 28;  // as the plugin

std::uint64_t bigEndian32(const unsigned char* p) {
    return std::uint64_t(p[0]) << 24 | std::uint64_t(p[1]) << 16 | std::uint64_t(p[2]) << 8 | p[3];
}

// PNG files of up to 8 bits per channel through lenslab's own codec (PngCodec.h), without the
// plugin; nothing for other files (16-bit PNGs keep their precision through OpenImageIO). Colour
// types all come as RGBA.
std::optional<DecodedImage> readEightBitPng(const std::string& path) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes(25);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), 25)) return std::nullopt;
    // The signature, then the IHDR chunk: width, height, bit depth.
    if (!std::equal(kSignature, kSignature + 8, bytes.begin()) || std::memcmp(&bytes[12], "IHDR", 4) != 0 || bytes[24] > 8)
        return std::nullopt;
    if (bigEndian32(&bytes[16]) * bigEndian32(&bytes[20]) > kMaxPixels) throw std::runtime_error("more than 268 Mpixels");
    bytes.insert(bytes.end(), std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    const RgbaImage rgba = decodePng(bytes);
    DecodedImage image;
    image.width = rgba.width;
    image.height = rgba.height;
    image.channels = 4;
    image.eightBit = true;
    image.pixels.reserve(rgba.rgba.size());
    for (std::uint8_t v : rgba.rgba) image.pixels.push_back(v / 255.0f);
    return image;
}

}  // namespace

DecodedImage readImageFile(const std::string& path) {
    if (isExrFile(path))
        if (std::optional<DecodedImage> exr = readExrFile(path)) return std::move(*exr);
    if (std::optional<DecodedImage> png = readEightBitPng(path)) return std::move(*png);
    const Plugin& p = plugin();
    if (!p.error.empty()) throw std::runtime_error(p.error);
    PluginImage raw{};
    char error[512] = {0};
    if (p.read(path.c_str(), &raw, error, sizeof error) != 0) throw std::runtime_error(error);
    DecodedImage image;
    image.width = raw.width;
    image.height = raw.height;
    image.channels = raw.channels;
    image.floatingPoint = raw.floatingPoint != 0;
    image.eightBit = raw.eightBit != 0;
    image.pixels.assign(raw.pixels, raw.pixels + std::size_t(raw.width) * raw.height * raw.channels);
    p.release(&raw);
    return image;
}

}  // namespace lenslab
