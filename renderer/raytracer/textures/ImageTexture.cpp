// pbrt-v3's imagemap texture: an image file over the texture coordinates, (0, 0) at the image's
// bottom-left corner, texel centres at half-integers, bilinearly interpolated.
//
// pbrt-v3 filters through a MIP map with the texture footprint from ray differentials. lenslab
// traces no ray differentials: a zero footprint makes pbrt-v3's trilinear and EWA lookups read the
// finest level bilinearly, which is what lenslab does for every "filter" but "point" (nearest
// texel); the pixel samples do the antialiasing. Unlike pbrt-v3, images whose sides are not powers
// of two are used as they are, not resampled up to powers of two.
#include <algorithm>
#include <cmath>

#include "materials/Material.h"
#include "textures/TexelGrid.h"
#include "textures/TextureClasses.h"
#include "textures/TextureMapping.h"

namespace lenslab {

namespace {

enum class Wrap { Repeat, Black, Clamp };

Vec3f asRgb(float v) { return {v, v, v}; }
Vec3f asRgb(Vec3f v) { return v; }

// The indices of the two texels on either side of coordinate `lower` + 0.5 along a side of n
// texels (lower: the floor of the texel-centre coordinate); -1 where the black wrap leaves the
// image. Coordinates beyond 2^30 texels are limited first (float precision has long run out
// there), so that the conversion to int is defined.
void texelPair(double lower, int n, Wrap wrap, int& i0, int& i1) {
    const int i = int(std::fmin(std::fmax(lower, -1073741824.0), 1073741824.0));
    switch (wrap) {
        case Wrap::Repeat:
            i0 = i % n;
            if (i0 < 0) i0 += n;
            i1 = i0 + 1 == n ? 0 : i0 + 1;
            return;
        case Wrap::Clamp:
            i0 = std::clamp(i, 0, n - 1);
            i1 = std::clamp(i + 1, 0, n - 1);
            return;
        case Wrap::Black:
            i0 = i >= 0 && i < n ? i : -1;
            i1 = i + 1 >= 0 && i + 1 < n ? i + 1 : -1;
            return;
    }
}

template <typename Stored>
class ImageTexture : public Texture {
public:
    using Value = decltype(std::declval<TexelGrid<Stored>>().linear(Stored{}));

    ImageTexture(TextureMapping2D map, std::shared_ptr<const TexelGrid<Stored>> grid, Wrap wrap, bool nearest,
                 float scale, bool invert)
        : map_(std::move(map)), grid_(std::move(grid)), wrap_(wrap), nearest_(nearest), scale_(scale), invert_(invert) {}

    Vec3f evaluate(const SurfaceHit& h) const override {
        const TexCoord c = map_.map(h);
        const Vec3f v = scale_ * asRgb(std::isfinite(c.s) && std::isfinite(c.t) ? lookup(c) : Value{});
        if (!invert_) return v;
        return {std::fmax(0.0f, 1 - v.x), std::fmax(0.0f, 1 - v.y), std::fmax(0.0f, 1 - v.z)};
    }

private:
    Value lookup(TexCoord c) const {
        const TexelGrid<Stored>& g = *grid_;
        const double x = double(c.s) * g.width - 0.5, y = double(c.t) * g.height - 0.5;
        const double x0 = std::floor(x), y0 = std::floor(y);
        int ix0, ix1, iy0, iy1;
        texelPair(x0, g.width, wrap_, ix0, ix1);
        texelPair(y0, g.height, wrap_, iy0, iy1);
        if (nearest_) return texel(x - x0 < 0.5 ? ix0 : ix1, y - y0 < 0.5 ? iy0 : iy1);
        const float fx = float(x - x0), fy = float(y - y0);
        return (1 - fy) * ((1 - fx) * texel(ix0, iy0) + fx * texel(ix1, iy0)) +
               fy * ((1 - fx) * texel(ix0, iy1) + fx * texel(ix1, iy1));
    }
    Value texel(int x, int y) const {
        if (x < 0 || y < 0) return Value{};
        return grid_->linear(grid_->texels[grid_->offset(x, y)]);
    }

    TextureMapping2D map_;
    std::shared_ptr<const TexelGrid<Stored>> grid_;
    Wrap wrap_;
    bool nearest_;
    float scale_;
    bool invert_;
};

// gamma: 1 decode sRGB, 0 linear, -1 as the file's format says (integer formats are encoded).
// 1 or 0 for "bool gamma" true or false; -1 when absent (or of another type, which
// checkAllUsed reports).
int gammaParam(const ParamSet& p) {
    const bool whenAbsentTrue = p.getBool("gamma", true), whenAbsentFalse = p.getBool("gamma", false);
    return whenAbsentTrue == whenAbsentFalse ? int(whenAbsentTrue) : -1;
}

Wrap wrapParam(const ParamSet& p) {
    const std::string wrap = p.getString("wrap", "repeat");
    if (wrap == "black") return Wrap::Black;
    if (wrap == "clamp") return Wrap::Clamp;
    if (wrap != "repeat") p.fail("\"wrap\" must be repeat, black or clamp, not \"" + wrap + "\"");
    return Wrap::Repeat;
}

}  // namespace

std::shared_ptr<const Texture> makeImageTexture(const TextureRequest& r) {
    const ParamSet& p = r.params;
    const std::string name = p.getString("filename", "");
    if (name.empty()) p.fail("imagemap needs \"string filename\"");
    TextureMapping2D map = TextureMapping2D::fromParams(p, r.textureToWorld);
    const Wrap wrap = wrapParam(p);
    const std::string filter = p.getString("filter", "bilinear");
    if (filter != "point" && filter != "bilinear" && filter != "trilinear" && filter != "ewa")
        p.fail("\"filter\" must be point, bilinear, trilinear or ewa, not \"" + filter + "\"");
    p.getBool("trilinear", false);  // pbrt-v3's MIP-map options: no effect without a footprint
    if (!(p.getFloat("maxanisotropy", 8) > 0)) p.fail("\"maxanisotropy\" must be positive");
    const float scale = float(p.getFloat("scale", 1));
    const bool invert = p.getBool("invert", false);
    const auto grid = sharedTexelGrid(r.resolve(name, p.where()), name, r.kind, gammaParam(p), p.where());
    return std::visit(
        [&](const auto& g) -> std::shared_ptr<const Texture> {
            using Stored = typename std::decay_t<decltype(g)>::StoredTexel;
            return std::make_shared<ImageTexture<Stored>>(std::move(map), std::shared_ptr<const TexelGrid<Stored>>(grid, &g),
                                                          wrap, filter == "point", scale, invert);
        },
        *grid);
}

}  // namespace lenslab
