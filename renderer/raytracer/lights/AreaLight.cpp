#include "lights/AreaLight.h"

#include <cmath>
#include <optional>

namespace lenslab {

namespace {

// A whole sphere emitting outward, seen from outside, is sampled by the cone of directions it
// subtends (uniform in solid angle), as pbrt-v3 does: by area, half the samples would land on its
// far side and the rest would carry the cosine's variance.
struct SphereCone {
    Vec3f centre;
    double radius = 0;
    // The cone's cos(theta max) from p; false when p is inside the sphere.
    bool from(Vec3f p, double& cosMax, double& distance) const {
        const Vec3f d = centre - p;
        distance = std::sqrt(double(dot(d, d)));
        if (!(distance > radius * 1.0001)) return false;
        const double sin2 = radius * radius / (distance * distance);
        cosMax = std::sqrt(std::max(0.0, 1 - sin2));
        return true;
    }
    // The cone's solid angle, 2 pi (1 - cos theta max), written to keep its digits for far spheres.
    static double solidAngle(double cosMax) {
        const double sin2 = 1 - cosMax * cosMax;
        return 2 * M_PI * sin2 / (1 + cosMax);
    }
};

std::optional<SphereCone> outwardSphere(const Shape& shape, std::size_t prim) {
    const auto sphere = shape.embreeSphere();
    if (!sphere) return std::nullopt;
    const ShapeSample probe = shape.samplePrimitive(prim, 0.3f, 0.6f);
    if (dot(probe.n, probe.p - sphere->centre) <= 0) return std::nullopt;  // ReverseOrientation: it lights its inside
    return SphereCone{sphere->centre, sphere->radius};
}

class DiffuseAreaLight : public Light {
public:
    DiffuseAreaLight(std::shared_ptr<const Shape> shape, std::size_t prim, Vec3f L, bool twoSided)
        : shape_(std::move(shape)), prim_(prim), L_(L), twoSided_(twoSided), cone_(outwardSphere(*shape_, prim)) {}

    bool sample(Vec3f p, float u1, float u2, LightSample& s) const override {
        double cosMax, distance;
        if (cone_ && cone_->from(p, cosMax, distance)) return sampleCone(p, cosMax, distance, u1, u2, s);
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
        double cosMax, distance;
        if (cone_ && cone_->from(p, cosMax, distance)) return float(1 / SphereCone::solidAngle(cosMax));
        const Vec3f d = at->p - p;
        const float cosL = std::fabs(dot(w, at->ng));
        return cosL > 1e-7f ? shape_->primitivePdf(prim_, *at) * dot(d, d) / cosL : 0.0f;
    }

    Vec3f emitted(const SurfaceHit* at, Vec3f w) const override {
        return at && (twoSided_ || dot(at->ng, w) < 0) ? L_ : Vec3f{};
    }

    Vec3f power() const override { return (twoSided_ ? 2.0f : 1.0f) * float(M_PI) * shape_->primitiveArea(prim_) * L_; }

private:
    bool sampleCone(Vec3f p, double cosMax, double distance, float u1, float u2, LightSample& s) const {
        const Vec3f axis = (cone_->centre - p) / float(distance);
        const double cosTheta = 1 - u1 * (1 - cosMax), sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
        const double phi = 2 * M_PI * u2;
        s.wi = normalize(Frame(axis).toWorld({float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta)}));
        // The near intersection with the sphere along wi.
        const double b = distance * cosTheta, r = cone_->radius;
        s.distance = float(b - std::sqrt(std::max(0.0, r * r - distance * distance * sinTheta * sinTheta)));
        s.pdf = float(1 / SphereCone::solidAngle(cosMax));
        s.radiance = L_;
        s.delta = false;
        return std::isfinite(s.pdf) && s.distance > 0;
    }

    std::shared_ptr<const Shape> shape_;
    std::size_t prim_;
    Vec3f L_;
    bool twoSided_;
    std::optional<SphereCone> cone_;
};

}  // namespace

std::unique_ptr<Light> makeDiffuseAreaLight(std::shared_ptr<const Shape> shape, std::size_t primitive, Vec3f L,
                                            bool twoSided) {
    return std::make_unique<DiffuseAreaLight>(std::move(shape), primitive, L, twoSided);
}

}  // namespace lenslab
