#pragma once
// PNG encoding and decoding of 8-bit RGBA pictures (libpng), shared by the diagram and the ray tracer.
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace lenslab {

class PngError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Row-major, top row first, 4 bytes per pixel (R, G, B, A).
struct RgbaImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// Encodes width*height RGBA8 pixels (top row first). Throws PngError on bad sizes.
std::vector<std::uint8_t> encodePngRgba8(int width, int height, const std::uint8_t* pixels);

// Decodes any PNG libpng reads (palette, grey, 16-bit, with or without alpha) to RGBA8.
// Throws PngError for data that is not a valid PNG.
RgbaImage decodePng(const std::vector<std::uint8_t>& bytes);

}  // namespace lenslab
