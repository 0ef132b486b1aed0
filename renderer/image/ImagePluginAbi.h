#pragma once
// The C interface between ImageFileReader and the OpenImageIO plugin (a dlopen'ed module).
#include <cstddef>

extern "C" {

struct PluginImage {
    int width, height, channels;
    int floatingPoint;  // 1: the file stores floats
    int eightBit;       // 1: 8-bit integers (values are multiples of 1/255)
    float* pixels;      // owned by the plugin until lenslab_free_image
};

// 0 on success; otherwise non-zero with a message in `error`.
typedef int (*ReadImageFunction)(const char* path, PluginImage* out, char* error, std::size_t errorSize);
typedef void (*FreeImageFunction)(PluginImage* image);
}
