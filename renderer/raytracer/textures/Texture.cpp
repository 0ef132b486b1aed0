#include "textures/Texture.h"

#include "textures/TextureClasses.h"

namespace lenslab {

namespace {

class ConstantTexture : public Texture {
public:
    explicit ConstantTexture(Vec3f value) : value_(value) {}
    Vec3f evaluate(const SurfaceHit&) const override { return value_; }

private:
    Vec3f value_;
};

using NamedTextures = std::map<std::string, std::shared_ptr<const Texture>>;

std::shared_ptr<const Texture> declared(const ParamSet& params, const std::string& param, const std::string& texture,
                                        const NamedTextures& own, const NamedTextures& other, const char* kind) {
    auto it = own.find(texture);
    if (it != own.end()) return it->second;
    const std::string hint = other.count(texture) ? " (\"" + texture + "\" is a texture of the other kind)" : "";
    params.fail("parameter \"" + param + "\" names an undeclared " + kind + " texture \"" + texture + "\"" + hint);
}

std::shared_ptr<const Texture> makeConstant(const TextureRequest& r) { return makeConstantTexture(r.value("value", 1)); }

struct TextureClass {
    const char* name;
    std::shared_ptr<const Texture> (*make)(const TextureRequest&);
    bool spectrumOnly;  // pbrt-v3 has no float version
};

constexpr TextureClass kClasses[] = {
    {"constant", makeConstant, false},
    {"scale", makeScaleTexture, false},
    {"mix", makeMixTexture, false},
    {"bilerp", makeBilerpTexture, false},
    {"imagemap", makeImageTexture, false},
    {"uv", makeUvTexture, true},
    {"checkerboard", makeCheckerboardTexture, false},
    {"dots", makeDotsTexture, false},
    {"fbm", makeFbmTexture, false},
    {"wrinkled", makeWrinkledTexture, false},
    {"windy", makeWindyTexture, false},
    {"marble", makeMarbleTexture, true},
};

}  // namespace

std::shared_ptr<const Texture> TextureRequest::operand(const std::string& name, float fallback) const {
    return kind == TextureKind::Float ? floatTextureParam(params, name, fallback, named)
                                      : textureParam(params, name, {fallback, fallback, fallback}, named);
}

Vec3f TextureRequest::value(const std::string& name, float fallback) const {
    if (kind == TextureKind::Spectrum) return params.getRgb(name, {fallback, fallback, fallback});
    const float x = float(params.getFloat(name, fallback));
    return {x, x, x};
}

std::shared_ptr<const Texture> makeConstantTexture(Vec3f value) { return std::make_shared<ConstantTexture>(value); }

std::shared_ptr<const Texture> textureParam(const ParamSet& params, const std::string& name, Vec3f fallback,
                                            const TextureMap& named) {
    const ColorOrTexture c = params.getColorOrTexture(name, fallback);
    if (c.texture) return declared(params, name, *c.texture, named.spectra, named.floats, "spectrum");
    return makeConstantTexture(c.color);
}

std::shared_ptr<const Texture> floatTextureParam(const ParamSet& params, const std::string& name, float fallback,
                                                 const TextureMap& named) {
    const ColorOrTexture c = params.getColorOrTexture(name, {fallback, fallback, fallback});
    if (c.texture) return declared(params, name, *c.texture, named.floats, named.spectra, "float");
    if (c.color.x != c.color.y || c.color.y != c.color.z)
        params.fail("parameter \"" + name + "\" needs a float or a float texture, not a colour");
    return makeConstantTexture(c.color);
}

std::shared_ptr<const Texture> makeTexture(const std::string& className, TextureKind kind, const ParamSet& params,
                                           const Transform& textureToWorld, const TextureMap& named,
                                           const PathResolver& resolve, std::vector<std::string>& warnings) {
    for (const TextureClass& c : kClasses) {
        if (className != c.name) continue;
        if (c.spectrumOnly && kind == TextureKind::Float)
            params.fail("\"" + className + "\" textures are spectrum textures only (as in pbrt-v3)");
        auto t = c.make(TextureRequest{params, kind, textureToWorld, named, resolve, warnings});
        params.checkAllUsed(warnings);
        return t;
    }
    std::string known;
    for (const TextureClass& c : kClasses) known += std::string(known.empty() ? "" : ", ") + c.name;
    params.fail("texture class \"" + className + "\" is not supported (" + known + ")");
}

}  // namespace lenslab
