// Textures made of other textures: scale (the product of two) and mix (a blend by a float texture).
#include "textures/TextureClasses.h"

namespace lenslab {

namespace {

class ScaleTexture : public Texture {
public:
    ScaleTexture(std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b) : a_(std::move(a)), b_(std::move(b)) {}
    Vec3f evaluate(const SurfaceHit& h) const override { return a_->evaluate(h) * b_->evaluate(h); }

private:
    std::shared_ptr<const Texture> a_, b_;
};

class MixTexture : public Texture {
public:
    MixTexture(std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b, std::shared_ptr<const Texture> amount)
        : a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const float t = amount_->evaluate(h).x;
        return (1 - t) * a_->evaluate(h) + t * b_->evaluate(h);
    }

private:
    std::shared_ptr<const Texture> a_, b_, amount_;
};

}  // namespace

// pbrt-v3 multiplies tex1 by tex2; pbrt-v4 names them tex and scale.
std::shared_ptr<const Texture> makeScaleTexture(const TextureRequest& r) {
    if (r.params.has("tex") || r.params.has("scale")) return std::make_shared<ScaleTexture>(r.operand("tex", 1), r.operand("scale", 1));
    return std::make_shared<ScaleTexture>(r.operand("tex1", 1), r.operand("tex2", 1));
}

std::shared_ptr<const Texture> makeMixTexture(const TextureRequest& r) {
    return std::make_shared<MixTexture>(r.operand("tex1", 0), r.operand("tex2", 1),
                                        floatTextureParam(r.params, "amount", 0.5f, r.named));
}

}  // namespace lenslab
