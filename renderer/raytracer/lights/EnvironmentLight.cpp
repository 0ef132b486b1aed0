// pbrt-v3's and pbrt-v4's infinite light with an environment map. Radiance is the map's texel in the direction
// (piecewise constant, like the sampling density), so that a sample's radiance / pdf is constant
// within a texel: bright texels such as a sun cost no more noise than their area deserves.
#include <cmath>

#include "core/Pi.h"
#include "lights/ImageLights.h"
#include "sampling/EqualAreaSphere.h"
#include "sampling/PiecewiseConstant.h"

namespace lenslab {

namespace {

std::vector<float> samplingWeights(const LinearImage& map, SphereLayout layout) {
    std::vector<float> w(map.texels.size());
    for (int y = 0; y < map.height; ++y) {
        // An equirectangular texel's solid angle is proportional to sin(theta) at its row; equal-area
        // texels all cover the same.
        const float sinTheta = layout == SphereLayout::EqualArea ? 1.0f : std::sin(kPif * (float(y) + 0.5f) / float(map.height));
        for (int x = 0; x < map.width; ++x) {
            const std::size_t i = std::size_t(y) * map.width + x;
            w[i] = luminance(map.texels[i]) * sinTheta;
        }
    }
    return w;
}

class EnvironmentLight : public Light {
public:
    EnvironmentLight(LinearImage map, const Transform& lightToWorld, SphereLayout layout)
        : map_(std::move(map)), toWorld_(lightToWorld), toLight_(inverse(lightToWorld)), layout_(layout),
          distribution_(samplingWeights(map_, layout), map_.width, map_.height), average_(map_.average()) {}

    bool sample(Vec3f p, float u1, float u2, LightSample& s) const override {
        float su, tv, mapPdf;
        distribution_.sample(u1, u2, su, tv, mapPdf);
        if (!(mapPdf > 0)) return false;
        Vec3f local;
        if (layout_ == SphereLayout::EqualArea) {
            local = equalAreaSquareToSphere(su, tv);
        } else {
            const float theta = tv * kPif, phi = su * 2.0f * kPif;
            const float sinTheta = std::sin(theta);
            if (!(sinTheta > 0)) return false;
            local = {sinTheta * std::cos(phi), sinTheta * std::sin(phi), std::cos(theta)};
        }
        s.wi = normalize(transformVector(toWorld_, local));
        s.distance = std::numeric_limits<float>::infinity();
        // Density and radiance from the direction itself, exactly as pdf() and emitted() find them:
        // a sample on a texel's edge would otherwise disagree with them after rounding.
        s.radiance = emitted(nullptr, s.wi);
        s.pdf = pdf(p, s.wi, nullptr);
        s.delta = false;
        return s.pdf > 0 && !isBlack(s.radiance);
    }

    float pdf(Vec3f, Vec3f w, const SurfaceHit* at) const override {
        if (at) return 0;
        float s, t, sinTheta;
        mapCoordinates(w, s, t, sinTheta);
        if (layout_ == SphereLayout::EqualArea) return distribution_.density(s, t) / (4.0f * kPif);
        return sinTheta > 0 ? distribution_.density(s, t) / (2.0f * kPif * kPif * sinTheta) : 0.0f;
    }

    Vec3f emitted(const SurfaceHit* at, Vec3f w) const override {
        if (at) return {};
        float s, t, sinTheta;
        mapCoordinates(w, s, t, sinTheta);
        return map_.lookup(s, t);
    }

    bool isInfinite() const override { return true; }
    // pbrt-v3's: the map's mean radiance through a disc of the scene's bounding radius.
    Vec3f power() const override { return kPif * radius_ * radius_ * average_; }
    void setSceneBounds(Vec3f, float radius) override { radius_ = radius; }

private:
    void mapCoordinates(Vec3f worldDirection, float& s, float& t, float& sinTheta) const {
        const Vec3f d = normalize(transformVector(toLight_, worldDirection));
        if (layout_ == SphereLayout::EqualArea) {
            equalAreaSphereToSquare(d, s, t);
            sinTheta = 1;
            return;
        }
        const float cosTheta = std::clamp(d.z, -1.0f, 1.0f);
        float phi = std::atan2(d.y, d.x);
        if (phi < 0) phi += 2.0f * kPif;
        s = phi / (2.0f * kPif);
        t = std::acos(cosTheta) / kPif;
        sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    }

    LinearImage map_;
    Transform toWorld_, toLight_;
    SphereLayout layout_;
    PiecewiseConstant2D distribution_;
    Vec3f average_;
    float radius_ = 1;
};

}  // namespace

std::unique_ptr<Light> makeEnvironmentLight(LinearImage map, const Transform& lightToWorld, SphereLayout layout) {
    return std::make_unique<EnvironmentLight>(std::move(map), lightToWorld, layout);
}

}  // namespace lenslab
