// pbrt-v3's imagemap texture: an image file over the texture coordinates, (0, 0) at the image's
// bottom-left corner, texel centres at half-integers, bilinearly interpolated.
//
// pbrt-v3 filters through a MIP map with the texture footprint from ray differentials. lenslab
// traces no ray differentials: a zero footprint makes pbrt-v3's trilinear and EWA lookups read the
// finest level bilinearly, which is what lenslab does for every "filter" but "point" (nearest
// texel); the pixel samples do the antialiasing. Unlike pbrt-v3, images whose sides are not powers
// of two are used as they are, not resampled up to powers of two.
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>

#include "Material.h"
#include "RgbImageFile.h"
#include "TextureClasses.h"
#include "TextureMapping.h"

namespace lenslab {

namespace {

enum class Wrap { Repeat, Black, Clamp };

// Linear texel values, row 0 at the bottom of the image.
template <typename T>
struct TexelGrid {
    int width = 0, height = 0;
    std::vector<T> texels;
};

float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

Vec3f asRgb(float v) { return {v, v, v}; }
Vec3f asRgb(Vec3f v) { return v; }

// The texel index for integer coordinate i (a floor, as a double so that any finite value is
// safe) along a side of n texels; -1 where the black wrap leaves the image.
int wrapIndex(double i, int n, Wrap wrap) {
    switch (wrap) {
        case Wrap::Repeat: {
            const double m = std::fmod(i, double(n));
            return int(m < 0 ? m + n : m);
        }
        case Wrap::Clamp: return int(std::fmin(std::fmax(i, 0.0), double(n - 1)));
        case Wrap::Black: return i < 0 || i >= n ? -1 : int(i);
    }
    return -1;
}

template <typename T>
class ImageTexture : public Texture {
public:
    ImageTexture(TextureMapping2D map, std::shared_ptr<const TexelGrid<T>> grid, Wrap wrap, bool nearest, float scale,
                 bool invert)
        : map_(std::move(map)), grid_(std::move(grid)), wrap_(wrap), nearest_(nearest), scale_(scale), invert_(invert) {}

    Vec3f evaluate(const SurfaceHit& h) const override {
        const TexCoord c = map_.map(h);
        const Vec3f v = scale_ * asRgb(std::isfinite(c.s) && std::isfinite(c.t) ? lookup(c) : T{});
        if (!invert_) return v;
        return {std::fmax(0.0f, 1 - v.x), std::fmax(0.0f, 1 - v.y), std::fmax(0.0f, 1 - v.z)};
    }

private:
    T lookup(TexCoord c) const {
        const double x = double(c.s) * grid_->width - 0.5, y = double(c.t) * grid_->height - 0.5;
        if (nearest_) return texel(index(std::floor(x + 0.5), grid_->width), index(std::floor(y + 0.5), grid_->height));
        const double x0 = std::floor(x), y0 = std::floor(y);
        const float fx = float(x - x0), fy = float(y - y0);
        const int ix0 = index(x0, grid_->width), ix1 = index(x0 + 1, grid_->width);
        const int iy0 = index(y0, grid_->height), iy1 = index(y0 + 1, grid_->height);
        return (1 - fy) * ((1 - fx) * texel(ix0, iy0) + fx * texel(ix1, iy0)) +
               fy * ((1 - fx) * texel(ix0, iy1) + fx * texel(ix1, iy1));
    }
    int index(double i, int n) const { return wrapIndex(i, n, wrap_); }
    T texel(int x, int y) const {
        if (x < 0 || y < 0) return T{};
        return grid_->texels[std::size_t(y) * grid_->width + x];
    }

    TextureMapping2D map_;
    std::shared_ptr<const TexelGrid<T>> grid_;
    Wrap wrap_;
    bool nearest_;
    float scale_;
    bool invert_;
};

// pbrt-v3 turns an image into a float texture through the luminance of its stored (still
// encoded) values, then decodes.
float texelValue(Vec3f rgb, bool decode, float*) {
    const float y = 0.212671f * rgb.x + 0.715160f * rgb.y + 0.072169f * rgb.z;
    return decode ? srgbDecode(y) : y;
}
Vec3f texelValue(Vec3f rgb, bool decode, Vec3f*) {
    return decode ? Vec3f{srgbDecode(rgb.x), srgbDecode(rgb.y), srgbDecode(rgb.z)} : rgb;
}

// gamma: 1 decode sRGB, 0 linear, -1 as the file's format says (integer formats are encoded).
template <typename T>
std::shared_ptr<const TexelGrid<T>> readGrid(const std::string& path, const std::string& name, int gamma,
                                              const SourceLocation& where) {
    const RgbImageFile file = readRgbImageFile(path, name, where);
    const bool decode = gamma < 0 ? file.integerFormat : gamma == 1;
    auto grid = std::make_shared<TexelGrid<T>>();
    grid->width = file.width;
    grid->height = file.height;
    grid->texels.resize(file.rgb.size());
    for (int y = 0; y < file.height; ++y)
        for (int x = 0; x < file.width; ++x)
            grid->texels[std::size_t(file.height - 1 - y) * file.width + x] =
                texelValue(file.rgb[std::size_t(y) * file.width + x], decode, static_cast<T*>(nullptr));
    return grid;
}

// Scenes often name one image in several textures (and a server renders many scenes): each file
// is read once while any texture still holds it. The key includes the file's time and size, so
// a changed file is read again.
template <typename T>
std::shared_ptr<const TexelGrid<T>> sharedGrid(const std::string& path, const std::string& name, int gamma,
                                               const SourceLocation& where) {
    static std::mutex mutex;
    static std::map<std::string, std::weak_ptr<const TexelGrid<T>>> cache;
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(path, ec).time_since_epoch().count();
    const auto size = std::filesystem::file_size(path, ec);
    const std::string key = path + '\n' + std::to_string(time) + ' ' + std::to_string(size) + ' ' + std::to_string(gamma);
    std::lock_guard<std::mutex> lock(mutex);
    if (auto grid = cache[key].lock()) return grid;
    auto grid = readGrid<T>(path, name, gamma, where);
    cache[key] = grid;
    return grid;
}

// 1 or 0 for "bool gamma" true or false; -1 when absent (or of another type, which
// checkAllUsed reports).
int gammaParam(const ParamSet& p) {
    const bool whenAbsentTrue = p.getBool("gamma", true), whenAbsentFalse = p.getBool("gamma", false);
    return whenAbsentTrue == whenAbsentFalse ? int(whenAbsentTrue) : -1;
}

template <typename T>
std::shared_ptr<const Texture> makeImage(const TextureRequest& r, const std::string& path, const std::string& name) {
    const ParamSet& p = r.params;
    TextureMapping2D map = TextureMapping2D::fromParams(p, r.textureToWorld);
    const std::string wrapName = p.getString("wrap", "repeat");
    Wrap wrap = Wrap::Repeat;
    if (wrapName == "black") wrap = Wrap::Black;
    else if (wrapName == "clamp") wrap = Wrap::Clamp;
    else if (wrapName != "repeat") p.fail("\"wrap\" must be repeat, black or clamp, not \"" + wrapName + "\"");
    const std::string filter = p.getString("filter", "bilinear");
    if (filter != "point" && filter != "bilinear" && filter != "trilinear" && filter != "ewa")
        p.fail("\"filter\" must be point, bilinear, trilinear or ewa, not \"" + filter + "\"");
    p.getBool("trilinear", false);  // pbrt-v3's MIP-map options: no effect without a footprint
    if (!(p.getFloat("maxanisotropy", 8) > 0)) p.fail("\"maxanisotropy\" must be positive");
    const int gamma = gammaParam(p);
    const float scale = float(p.getFloat("scale", 1));
    const bool invert = p.getBool("invert", false);
    return std::make_shared<ImageTexture<T>>(std::move(map), sharedGrid<T>(path, name, gamma, p.where()), wrap,
                                             filter == "point", scale, invert);
}

}  // namespace

std::shared_ptr<const Texture> makeImageTexture(const TextureRequest& r) {
    const std::string name = r.params.getString("filename", "");
    if (name.empty()) r.params.fail("imagemap needs \"string filename\"");
    const std::string path = r.resolve(name, r.params.where());
    return r.kind == TextureKind::Float ? makeImage<float>(r, path, name) : makeImage<Vec3f>(r, path, name);
}

}  // namespace lenslab
