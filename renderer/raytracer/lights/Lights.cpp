#include <cmath>
#include <optional>

#include "lights/ImageLights.h"
#include "lights/Light.h"
#include "lights/PointLight.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// pbrt-v3's spot: full intensity inside coneangle - conedeltaangle, a smooth falloff to zero at
// coneangle.
class SpotLight : public PointLight {
public:
    SpotLight(Vec3f position, Vec3f axis, Vec3f intensity, float coneAngle, float coneDelta)
        : PointLight(position, intensity), axis_(axis), cosTotal_(std::cos(coneAngle * float(M_PI) / 180)),
          cosFalloff_(std::cos((coneAngle - coneDelta) * float(M_PI) / 180)) {}
    Vec3f power() const override {
        return 2.0f * float(M_PI) * (1.0f - 0.5f * (cosFalloff_ + cosTotal_)) * intensity_;
    }

protected:
    Vec3f directionalScale(Vec3f w) const override {
        const float c = dot(w, axis_);
        if (c < cosTotal_) return {};
        if (c >= cosFalloff_) return {1, 1, 1};
        const float d = (c - cosTotal_) / (cosFalloff_ - cosTotal_);
        const float falloff = (d * d) * (d * d);
        return {falloff, falloff, falloff};
    }

private:
    Vec3f axis_;
    float cosTotal_, cosFalloff_;
};

class DistantLight : public Light {
public:
    DistantLight(Vec3f towardLight, Vec3f radiance) : toward_(towardLight), radiance_(radiance) {}
    bool sample(Vec3f, float, float, LightSample& s) const override {
        s.wi = toward_;
        s.distance = kInf;
        s.radiance = radiance_;
        s.pdf = 1;
        s.delta = true;
        return true;
    }
    float pdf(Vec3f, Vec3f, const SurfaceHit*) const override { return 0; }
    Vec3f emitted(const SurfaceHit*, Vec3f) const override { return {}; }
    bool isDelta() const override { return true; }
    Vec3f power() const override { return float(M_PI) * radius_ * radius_ * radiance_; }
    void setSceneBounds(Vec3f, float radius) override { radius_ = radius; }

private:
    Vec3f toward_, radiance_;
    float radius_ = 1;
};

// The constant "infinite" light (no map): uniform radiance from every direction, sampled uniformly.
class InfiniteLight : public Light {
public:
    explicit InfiniteLight(Vec3f radiance) : radiance_(radiance) {}
    bool sample(Vec3f, float u1, float u2, LightSample& s) const override {
        s.wi = uniformSphere(u1, u2);
        s.distance = kInf;
        s.radiance = radiance_;
        s.pdf = 1.0f / (4.0f * float(M_PI));
        s.delta = false;
        return true;
    }
    float pdf(Vec3f, Vec3f, const SurfaceHit*) const override { return 1.0f / (4.0f * float(M_PI)); }
    Vec3f emitted(const SurfaceHit*, Vec3f) const override { return radiance_; }
    bool isInfinite() const override { return true; }
    Vec3f power() const override { return float(M_PI) * radius_ * radius_ * radiance_; }  // as pbrt-v3
    void setSceneBounds(Vec3f, float radius) override { radius_ = radius; }

private:
    Vec3f radiance_;
    float radius_ = 1;
};

}  // namespace

std::unique_ptr<Light> makeLight(const std::string& type, const ParamSet& p, const Transform& toWorld,
                                 const PathResolver& resolve, std::vector<std::string>& warnings) {
    const Vec3f scale = p.getRgb("scale", {1, 1, 1});
    const auto image = [&]() -> std::optional<LinearImage> {
        const std::string name = p.getString("mapname", "");
        if (name.empty()) return std::nullopt;
        return readLinearImage(resolve(name, p.where()), name, p.where());
    };
    std::unique_ptr<Light> light;
    if (type == "point") {
        const Vec3f from = transformPoint(toWorld, p.getPoint("from", {0, 0, 0}));
        light = std::make_unique<PointLight>(from, scale * p.getRgb("I", {1, 1, 1}));
    } else if (type == "spot") {
        const Vec3f fromL = p.getPoint("from", {0, 0, 0}), toL = p.getPoint("to", {0, 0, 1});
        const Vec3f axis = transformVector(toWorld, toL - fromL);
        if (!(length(axis) > 0)) p.fail("\"from\" and \"to\" must differ");
        const float cone = float(p.getFloat("coneangle", 30)), delta = float(p.getFloat("conedeltaangle", 5));
        if (!(cone > 0 && cone <= 180) || !(delta >= 0 && delta <= cone)) p.fail("coneangle must lie in (0, 180] and conedeltaangle in [0, coneangle]");
        light = std::make_unique<SpotLight>(transformPoint(toWorld, fromL), normalize(axis),
                                            scale * p.getRgb("I", {1, 1, 1}), cone, delta);
    } else if (type == "distant") {
        const Vec3f fromL = p.getPoint("from", {0, 0, 0}), toL = p.getPoint("to", {0, 0, 1});
        const Vec3f toward = transformVector(toWorld, fromL - toL);
        if (!(length(toward) > 0)) p.fail("\"from\" and \"to\" must differ");
        light = std::make_unique<DistantLight>(normalize(toward), scale * p.getRgb("L", {1, 1, 1}));
    } else if (type == "infinite") {
        const Vec3f L = scale * p.getRgb("L", {1, 1, 1});
        if (std::optional<LinearImage> map = image()) {
            for (Vec3f& texel : map->texels) texel = L * texel;
            light = makeEnvironmentLight(std::move(*map), toWorld);
        } else {
            light = std::make_unique<InfiniteLight>(L);
        }
    } else if (type == "goniometric") {
        light = makeGoniometricLight(image(), scale * p.getRgb("I", {1, 1, 1}), toWorld);
    } else if (type == "projection") {
        const float fov = float(p.getFloat("fov", 45));
        if (!(fov > 0 && fov < 180)) p.fail("fov must lie in (0, 180) degrees");
        light = makeProjectionLight(image(), scale * p.getRgb("I", {1, 1, 1}), fov, toWorld);
    } else {
        p.fail("light \"" + type + "\" is not supported (point, spot, distant, infinite, goniometric, projection)");
    }
    p.checkAllUsed(warnings, {"nsamples", "samples"});
    return light;
}

}  // namespace lenslab
