#include "Texture.h"

#include <cmath>
#include <fstream>
#include <iterator>

#include "Material.h"
#include "PngCodec.h"

namespace lenslab {

namespace {

class ConstantTexture : public Texture {
public:
    explicit ConstantTexture(Vec3f value) : value_(value) {}
    Vec3f evaluate(const SurfaceHit&) const override { return value_; }

private:
    Vec3f value_;
};

// pbrt's planar (u, v) mapping: s = uscale u + udelta, t = vscale v + vdelta.
struct UvMapping {
    float uscale = 1, vscale = 1, udelta = 0, vdelta = 0;
    explicit UvMapping(const ParamSet& p)
        : uscale(float(p.getFloat("uscale", 1))), vscale(float(p.getFloat("vscale", 1))),
          udelta(float(p.getFloat("udelta", 0))), vdelta(float(p.getFloat("vdelta", 0))) {}
};

class CheckerboardTexture : public Texture {
public:
    CheckerboardTexture(UvMapping map, std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b)
        : map_(map), a_(std::move(a)), b_(std::move(b)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const float s = map_.uscale * h.u + map_.udelta, t = map_.vscale * h.v + map_.vdelta;
        const long parity = static_cast<long>(std::floor(s)) + static_cast<long>(std::floor(t));
        return (parity & 1) == 0 ? a_->evaluate(h) : b_->evaluate(h);
    }

private:
    UvMapping map_;
    std::shared_ptr<const Texture> a_, b_;
};

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// A PNG image, repeated over (u, v), bilinearly filtered; v = 0 is the image's bottom row (pbrt).
class ImageTexture : public Texture {
public:
    ImageTexture(UvMapping map, int w, int h, std::vector<Vec3f> texels, float scale)
        : map_(map), w_(w), h_(h), texels_(std::move(texels)), scale_(scale) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const float s = (map_.uscale * h.u + map_.udelta) * w_ - 0.5f;
        const float t = (1.0f - (map_.vscale * h.v + map_.vdelta)) * h_ - 0.5f;
        const float fs = std::floor(s), ft = std::floor(t);
        const float ds = s - fs, dt = t - ft;
        const int x = static_cast<int>(fs), y = static_cast<int>(ft);
        const Vec3f c = (1 - ds) * (1 - dt) * texel(x, y) + ds * (1 - dt) * texel(x + 1, y) +
                        (1 - ds) * dt * texel(x, y + 1) + ds * dt * texel(x + 1, y + 1);
        return scale_ * c;
    }

private:
    Vec3f texel(int x, int y) const {
        x %= w_; y %= h_;
        if (x < 0) x += w_;
        if (y < 0) y += h_;
        return texels_[static_cast<std::size_t>(y) * w_ + x];
    }
    UvMapping map_;
    int w_, h_;
    std::vector<Vec3f> texels_;
    float scale_;
};

std::shared_ptr<const Texture> loadImageTexture(const ParamSet& p, const PathResolver& resolve) {
    const std::string name = p.getString("filename", "");
    if (name.empty()) p.fail("imagemap needs \"string filename\"");
    const bool gamma = p.getBool("gamma", true);  // 8-bit PNGs hold sRGB-encoded values
    const float scale = float(p.getFloat("scale", 1));
    const std::string path = resolve(name, p.where());
    std::ifstream in(path, std::ios::binary);
    if (!in) p.fail("cannot open image '" + name + "'");
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    RgbaImage img;
    try {
        img = decodePng(bytes);
    } catch (const PngError& e) {
        p.fail("image '" + name + "' is not a readable PNG (" + e.what() + "); only PNG is supported");
    }
    std::vector<Vec3f> texels(static_cast<std::size_t>(img.width) * img.height);
    for (std::size_t i = 0; i < texels.size(); ++i) {
        Vec3f c{img.rgba[4 * i] / 255.0f, img.rgba[4 * i + 1] / 255.0f, img.rgba[4 * i + 2] / 255.0f};
        if (gamma) c = {srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z)};
        texels[i] = c;
    }
    return std::make_shared<ImageTexture>(UvMapping(p), img.width, img.height, std::move(texels), scale);
}

}  // namespace

std::shared_ptr<const Texture> makeConstantTexture(Vec3f value) { return std::make_shared<ConstantTexture>(value); }

std::shared_ptr<const Texture> textureParam(const ParamSet& params, const std::string& name, Vec3f fallback,
                                            const TextureMap& named) {
    const ColorOrTexture c = params.getColorOrTexture(name, fallback);
    if (!c.texture) return makeConstantTexture(c.color);
    auto it = named.find(*c.texture);
    if (it == named.end()) params.fail("parameter \"" + name + "\" names an undeclared texture \"" + *c.texture + "\"");
    return it->second;
}

std::shared_ptr<const Texture> makeTexture(const std::string& className, const ParamSet& params,
                                           const TextureMap& named, const PathResolver& resolve,
                                           std::vector<std::string>& warnings) {
    std::shared_ptr<const Texture> t;
    if (className == "constant") {
        t = textureParam(params, "value", {1, 1, 1}, named);
    } else if (className == "checkerboard") {
        if (params.getInt("dimension", 2) != 2) params.fail("only 2D checkerboards are supported");
        auto a = textureParam(params, "tex1", {1, 1, 1}, named);
        auto b = textureParam(params, "tex2", {0, 0, 0}, named);
        const std::string mapping = params.getString("mapping", "uv");
        if (mapping != "uv") params.fail("texture mapping \"" + mapping + "\" is not supported (only uv)");
        t = std::make_shared<CheckerboardTexture>(UvMapping(params), std::move(a), std::move(b));
    } else if (className == "imagemap") {
        t = loadImageTexture(params, resolve);
    } else {
        params.fail("texture class \"" + className + "\" is not supported (checkerboard, constant, imagemap)");
    }
    params.checkAllUsed(warnings, {"aamode", "filter", "maxanisotropy", "trilinear", "wrap"});
    return t;
}

}  // namespace lenslab
