#include "ImageFileReader.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

#include "ExrFileReader.h"
#include "ImagePluginAbi.h"

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

}  // namespace

DecodedImage readImageFile(const std::string& path) {
    if (isExrFile(path))
        if (std::optional<DecodedImage> exr = readExrFile(path)) return std::move(*exr);
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
