// Textures that are plain functions of the texture coordinates (s, t): uv (s and t as red and
// green) and bilerp (bilinear between four corner values).
#include <cmath>

#include "textures/TextureClasses.h"
#include "textures/TextureMapping.h"

namespace lenslab {

namespace {

class UvTexture : public Texture {
public:
    explicit UvTexture(TextureMapping2D map) : map_(std::move(map)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const TexCoord c = map_.map(h);
        return {c.s - std::floor(c.s), c.t - std::floor(c.t), 0};
    }

private:
    TextureMapping2D map_;
};

// v00 at (0, 0), v10 at (1, 0), v01 at (0, 1); outside the unit square it extrapolates, as pbrt-v3.
class BilerpTexture : public Texture {
public:
    BilerpTexture(TextureMapping2D map, Vec3f v00, Vec3f v01, Vec3f v10, Vec3f v11)
        : map_(std::move(map)), v00_(v00), v01_(v01), v10_(v10), v11_(v11) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const TexCoord c = map_.map(h);
        return (1 - c.s) * ((1 - c.t) * v00_ + c.t * v01_) + c.s * ((1 - c.t) * v10_ + c.t * v11_);
    }

private:
    TextureMapping2D map_;
    Vec3f v00_, v01_, v10_, v11_;
};

}  // namespace

std::shared_ptr<const Texture> makeUvTexture(const TextureRequest& r) {
    return std::make_shared<UvTexture>(TextureMapping2D::fromParams(r.params, r.textureToWorld));
}

std::shared_ptr<const Texture> makeBilerpTexture(const TextureRequest& r) {
    return std::make_shared<BilerpTexture>(TextureMapping2D::fromParams(r.params, r.textureToWorld), r.value("v00", 0),
                                           r.value("v01", 1), r.value("v10", 0), r.value("v11", 1));
}

}  // namespace lenslab
