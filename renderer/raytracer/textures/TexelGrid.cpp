#include "textures/TexelGrid.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>

#include "images/RgbImageFile.h"

namespace lenslab {

namespace {

// The linear value of each byte: sRGB-decoded, or k / 255.
const float* byteValues(bool decode) {
    static const auto tables = [] {
        std::array<std::array<float, 256>, 2> t{};
        for (int k = 0; k < 256; ++k) {
            t[0][k] = float(k) / 255.0f;
            t[1][k] = srgbDecode(float(k) / 255.0f);
        }
        return t;
    }();
    return tables[decode].data();
}

// pbrt-v3 makes a float texture from the luminance of the stored (still encoded) values, then
// decodes.
AnyTexelGrid texelGrid(const RgbImageFile& file, TextureKind kind, int gamma) {
    const bool decode = gamma < 0 ? file.integerFormat : gamma == 1;
    const auto fill = [&file](auto grid, auto convert) {
        for (int y = 0; y < file.height; ++y)
            for (int x = 0; x < file.width; ++x)
                grid.texels[grid.offset(x, file.height - 1 - y)] = convert(file.rgb[std::size_t(y) * file.width + x]);
        return grid;
    };
    if (kind == TextureKind::Float)
        return fill(TexelGrid<float>(file.width, file.height), [decode](Vec3f c) {
            const float y = 0.212671f * c.x + 0.715160f * c.y + 0.072169f * c.z;
            return decode ? srgbDecode(y) : y;
        });
    if (file.eightBit) {
        TexelGrid<Rgb8> grid(file.width, file.height);
        grid.bytes = byteValues(decode);
        const auto byte = [](float v) { return std::uint8_t(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255)); };
        return fill(std::move(grid), [&](Vec3f c) { return Rgb8{byte(c.x), byte(c.y), byte(c.z)}; });
    }
    return fill(TexelGrid<Vec3f>(file.width, file.height), [decode](Vec3f c) {
        return decode ? Vec3f{srgbDecode(c.x), srgbDecode(c.y), srgbDecode(c.z)} : c;
    });
}

}  // namespace

// Scenes often name one image in several textures (and a server renders many scenes): each file
// is read once while any texture still holds it. The key includes the file's time and size, so
// a changed file is read again.
std::shared_ptr<const AnyTexelGrid> sharedTexelGrid(const std::string& path, const std::string& name, TextureKind kind,
                                                    int gamma, const SourceLocation& where) {
    static std::mutex mutex;
    static std::map<std::string, std::weak_ptr<const AnyTexelGrid>> cache;
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(path, ec).time_since_epoch().count();
    const auto size = std::filesystem::file_size(path, ec);
    const std::string key = path + '\n' + std::to_string(time) + ' ' + std::to_string(size) + ' ' +
                            std::to_string(int(kind)) + ' ' + std::to_string(gamma);
    std::lock_guard<std::mutex> lock(mutex);
    if (auto grid = cache[key].lock()) return grid;
    auto grid = std::make_shared<const AnyTexelGrid>(texelGrid(readRgbImageFile(path, name, where), kind, gamma));
    for (auto it = cache.begin(); it != cache.end();) it = it->second.expired() ? cache.erase(it) : std::next(it);
    cache[key] = grid;
    return grid;
}

}  // namespace lenslab
