#include "AreaLight.h"

#include <cmath>

namespace lenslab {

namespace {

class DiffuseAreaLight : public Light {
public:
    DiffuseAreaLight(std::shared_ptr<const Shape> shape, std::size_t prim, Vec3f L, bool twoSided)
        : shape_(std::move(shape)), prim_(prim), L_(L), twoSided_(twoSided) {}

    bool sample(Vec3f p, float u1, float u2, LightSample& s) const override {
        const ShapeSample q = shape_->samplePrimitive(prim_, u1, u2);
        const Vec3f d = q.p - p;
        const float d2 = dot(d, d);
        if (!(d2 > 0) || !(q.pdf > 0)) return false;
        s.distance = std::sqrt(d2);
        s.wi = d / s.distance;
        const float cosL = dot(-s.wi, q.n);
        if (!twoSided_ && cosL <= 0) return false;
        if (std::fabs(cosL) < 1e-7f) return false;
        s.pdf = q.pdf * d2 / std::fabs(cosL);
        s.radiance = L_;
        s.delta = false;
        return std::isfinite(s.pdf);
    }

    float pdf(Vec3f p, Vec3f w, const SurfaceHit* at) const override {
        if (!at) return 0;
        const Vec3f d = at->p - p;
        const float cosL = std::fabs(dot(w, at->ng));
        return cosL > 1e-7f ? shape_->primitivePdf(prim_, *at) * dot(d, d) / cosL : 0.0f;
    }

    Vec3f emitted(const SurfaceHit* at, Vec3f w) const override {
        return at && (twoSided_ || dot(at->ng, w) < 0) ? L_ : Vec3f{};
    }

    Vec3f power() const override { return (twoSided_ ? 2.0f : 1.0f) * float(M_PI) * shape_->primitiveArea(prim_) * L_; }

private:
    std::shared_ptr<const Shape> shape_;
    std::size_t prim_;
    Vec3f L_;
    bool twoSided_;
};

}  // namespace

std::unique_ptr<Light> makeDiffuseAreaLight(std::shared_ptr<const Shape> shape, std::size_t primitive, Vec3f L,
                                            bool twoSided) {
    return std::make_unique<DiffuseAreaLight>(std::move(shape), primitive, L, twoSided);
}

}  // namespace lenslab
