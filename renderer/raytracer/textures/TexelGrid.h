#pragma once
// Images as the image textures store them: linear values, rows counted from the image's bottom,
// in 4x4 tiles; 8-bit files keep their bytes. Each file is read once while textures hold it.
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/ParamSet.h"
#include "textures/Texture.h"
#include "core/Vec3f.h"

namespace lenslab {

// An 8-bit file's texel as stored: a quarter of the memory of floats, since lookups into large
// images are bound by memory traffic.
struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0, unused = 0;
};

// Texels in 4x4 tiles, rows counted from the image's bottom: the four texels of a bilinear lookup
// mostly lie in one tile, one cache line for 4-byte texels.
template <typename Stored>
struct TexelGrid {
    using StoredTexel = Stored;
    int width = 0, height = 0;
    std::vector<Stored> texels;
    const float* bytes = nullptr;  // Rgb8: the linear value of each byte (sRGB-decoded or k / 255)

    TexelGrid(int w, int h) : width(w), height(h), texels(std::size_t((w + 3) / 4) * ((h + 3) / 4) * 16) {}
    std::size_t offset(int x, int y) const {
        return (std::size_t(y >> 2) * ((width + 3) >> 2) + (x >> 2)) * 16 + ((y & 3) << 2) + (x & 3);
    }
    float linear(float v) const { return v; }
    Vec3f linear(Vec3f v) const { return v; }
    Vec3f linear(Rgb8 v) const { return {bytes[v.r], bytes[v.g], bytes[v.b]}; }
};

using AnyTexelGrid = std::variant<TexelGrid<float>, TexelGrid<Rgb8>, TexelGrid<Vec3f>>;

// The texels of image file `path` (`name` as the scene gave it) for a texture of `kind`: float
// textures hold the luminance. gamma: 1 decode sRGB, 0 linear, -1 as the file's format says
// (integer formats are encoded). A SceneError at `where` when the file cannot be read.
std::shared_ptr<const AnyTexelGrid> sharedTexelGrid(const std::string& path, const std::string& name, TextureKind kind,
                                                    int gamma, const SourceLocation& where);

}  // namespace lenslab
