// pbrt-v3's checkerboards: over the texture coordinates (dimension 2) or in the texture's space
// (dimension 3); cells whose integer parts sum to an even number take tex1, the others tex2.
#include <cmath>

#include "textures/TextureClasses.h"
#include "textures/TextureMapping.h"

namespace lenslab {

namespace {

// fmod of doubles keeps the parity defined for negative and huge coordinates alike.
bool evenCell(double integerSum) { return std::fmod(integerSum, 2.0) == 0; }

class Checkerboard2D : public Texture {
public:
    Checkerboard2D(TextureMapping2D map, std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b)
        : map_(std::move(map)), a_(std::move(a)), b_(std::move(b)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const TexCoord c = map_.map(h);
        return evenCell(std::floor(double(c.s)) + std::floor(double(c.t))) ? a_->evaluate(h) : b_->evaluate(h);
    }

private:
    TextureMapping2D map_;
    std::shared_ptr<const Texture> a_, b_;
};

class Checkerboard3D : public Texture {
public:
    Checkerboard3D(TextureMapping3D map, std::shared_ptr<const Texture> a, std::shared_ptr<const Texture> b)
        : map_(std::move(map)), a_(std::move(a)), b_(std::move(b)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const Vec3f p = map_.map(h);
        const double sum = std::floor(double(p.x)) + std::floor(double(p.y)) + std::floor(double(p.z));
        return evenCell(sum) ? a_->evaluate(h) : b_->evaluate(h);
    }

private:
    TextureMapping3D map_;
    std::shared_ptr<const Texture> a_, b_;
};

}  // namespace

std::shared_ptr<const Texture> makeCheckerboardTexture(const TextureRequest& r) {
    const int dimension = r.params.getInt("dimension", 2);
    auto a = r.operand("tex1", 1);
    auto b = r.operand("tex2", 0);
    if (dimension == 3) return std::make_shared<Checkerboard3D>(TextureMapping3D(r.textureToWorld), std::move(a), std::move(b));
    if (dimension != 2) r.params.fail("checkerboard \"dimension\" must be 2 or 3, not " + std::to_string(dimension));
    // pbrt-v3's closed-form box filter needs the texture footprint from ray differentials, which
    // lenslab does not trace: checks are point-sampled and the pixel samples antialias them.
    const std::string aa = r.params.getString("aamode", "closedform");
    if (r.params.has("aamode") && aa != "none")
        r.warnings.push_back(describe(r.params.where()) + ": aamode \"" + aa +
                             "\": no ray differentials in lenslab, the checks are point-sampled (antialiased by the pixel samples)");
    return std::make_shared<Checkerboard2D>(TextureMapping2D::fromParams(r.params, r.textureToWorld), std::move(a), std::move(b));
}

}  // namespace lenslab
