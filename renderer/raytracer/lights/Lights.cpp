#include <cmath>
#include <optional>

#include "lights/ImageLights.h"
#include "lights/Light.h"
#include "lights/Pbrt4Emission.h"
#include "lights/PointLight.h"
#include "sampling/EqualAreaSphere.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {

constexpr float kInfiniteDistance = std::numeric_limits<float>::infinity();

// A spot: full intensity inside coneangle - conedeltaangle, falling to zero at coneangle, as
// pbrt-v3 does (the fourth power of the cosines' fraction) or pbrt-v4 (its smoothstep).
class SpotLight : public PointLight {
public:
    SpotLight(Vec3f position, Vec3f axis, Vec3f intensity, float coneAngle, float coneDelta, SceneDialect dialect)
        : PointLight(position, intensity), axis_(axis), cosTotal_(std::cos(coneAngle * float(M_PI) / 180)),
          cosFalloff_(std::cos((coneAngle - coneDelta) * float(M_PI) / 180)), dialect_(dialect) {}
    Vec3f power() const override { return unitPower(cosTotal_, cosFalloff_) * intensity_; }
    // pbrt's estimate of the power of unit intensity, the falloff counted as half.
    static float unitPower(float cosTotal, float cosFalloff) {
        return 2.0f * float(M_PI) * (1.0f - 0.5f * (cosFalloff + cosTotal));
    }

protected:
    Vec3f directionalScale(Vec3f w) const override {
        const float c = dot(w, axis_);
        if (c < cosTotal_) return {};
        if (c >= cosFalloff_) return {1, 1, 1};
        const float d = (c - cosTotal_) / (cosFalloff_ - cosTotal_);
        const float falloff = dialect_ == SceneDialect::PbrtV4 ? d * d * (3 - 2 * d) : (d * d) * (d * d);
        return {falloff, falloff, falloff};
    }

private:
    Vec3f axis_;
    float cosTotal_, cosFalloff_;
    SceneDialect dialect_;
};

class DistantLight : public Light {
public:
    DistantLight(Vec3f towardLight, Vec3f radiance) : toward_(towardLight), radiance_(radiance) {}
    bool sample(Vec3f, float, float, LightSample& s) const override {
        s.wi = toward_;
        s.distance = kInfiniteDistance;
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
        s.distance = kInfiniteDistance;
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

// pbrt-v4's "illuminance" for an environment map: the factor that makes the map deliver E to a
// surface facing light-space +z (the map's sum of luminance times cos theta over the upper
// hemisphere, each equal-area texel covering 4 pi / texels).
float mapIlluminanceFactor(const ParamSet& p, const LinearImage& map) {
    const double target = p.getFloat("illuminance", -1);
    if (target <= 0) return 1;
    double e = 0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const Vec3f d = equalAreaSquareToSphere((float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height));
            if (d.z > 0) e += luminance(map.texels[std::size_t(y) * map.width + x]) * d.z;
        }
    e *= 4 * M_PI / double(map.texels.size());
    if (!(e > 0)) p.fail("\"illuminance\" given for a map that lights nothing from above");
    return float(target / e);
}

// The lights of pbrt-v4 files: emission read and normalised as pbrt-v4 does (lights/Pbrt4Emission.h),
// maps as equal-area squares, the spot's smoothstep falloff.
// A spot light's place, axis and cone, which pbrt-v3 and pbrt-v4 give alike.
struct SpotPlacement {
    Vec3f from, axis;
    float cone, delta;  // degrees
};

SpotPlacement spotPlacement(const ParamSet& p, const Transform& toWorld) {
    const Vec3f fromL = p.getPoint("from", {0, 0, 0}), toL = p.getPoint("to", {0, 0, 1});
    const Vec3f axis = transformVector(toWorld, toL - fromL);
    if (!(length(axis) > 0)) p.fail("\"from\" and \"to\" must differ");
    const float cone = float(p.getFloat("coneangle", 30)), delta = float(p.getFloat("conedeltaangle", 5));
    if (!(cone > 0 && cone <= 180) || !(delta >= 0 && delta <= cone)) p.fail("coneangle must lie in (0, 180] and conedeltaangle in [0, coneangle]");
    return {transformPoint(toWorld, fromL), normalize(axis), cone, delta};
}

// The unit direction toward a distant light (from "to" to "from"), alike in both pbrts.
Vec3f distantDirection(const ParamSet& p, const Transform& toWorld) {
    const Vec3f fromL = p.getPoint("from", {0, 0, 0}), toL = p.getPoint("to", {0, 0, 1});
    const Vec3f toward = transformVector(toWorld, fromL - toL);
    if (!(length(toward) > 0)) p.fail("\"from\" and \"to\" must differ");
    return normalize(toward);
}

std::unique_ptr<Light> makePbrt4Light(const std::string& type, const ParamSet& p, const Transform& toWorld,
                                      const PathResolver& resolve, std::vector<std::string>& warnings) {
    const auto image = [&]() -> std::optional<LinearImage> {
        const std::string name = p.getString("filename", "");
        if (name.empty()) return std::nullopt;
        return readLinearImage(resolve(name, p.where()), name, p.where());
    };
    const auto squareImage = [&]() {
        std::optional<LinearImage> map = image();
        if (map && map->width != map->height)
            p.fail("pbrt-v4 needs a square (equal-area) image, not " + std::to_string(map->width) + " x " + std::to_string(map->height));
        return map;
    };
    const auto noPower = [&] {
        if (p.has("power")) warnings.push_back(describe(p.where()) + ": \"power\" not applied to this light type");
    };
    if (type == "point") {
        const Vec3f I = pbrt4Emission(p, "I") * pbrt4PowerFactor(p, 4 * float(M_PI));
        return std::make_unique<PointLight>(transformPoint(toWorld, p.getPoint("from", {0, 0, 0})), I);
    }
    if (type == "spot") {
        const SpotPlacement s = spotPlacement(p, toWorld);
        const float unit = SpotLight::unitPower(std::cos(s.cone * float(M_PI) / 180), std::cos((s.cone - s.delta) * float(M_PI) / 180));
        return std::make_unique<SpotLight>(s.from, s.axis, pbrt4Emission(p, "I") * pbrt4PowerFactor(p, unit), s.cone, s.delta,
                                           SceneDialect::PbrtV4);
    }
    if (type == "distant") {
        const double illuminance = p.getFloat("illuminance", -1);  // on a surface facing the light
        const Vec3f L = pbrt4Emission(p, "L") * (illuminance > 0 ? float(illuminance) : 1.0f);
        return std::make_unique<DistantLight>(distantDirection(p, toWorld), L);
    }
    if (type == "infinite") {
        noPower();
        if (std::optional<LinearImage> map = squareImage()) {
            if (p.has("L")) p.fail("give \"L\" or \"filename\", not both (as pbrt-v4)");
            const float scale = float(p.getFloat("scale", 1)) * mapIlluminanceFactor(p, *map);
            for (Vec3f& texel : map->texels) texel = scale * texel;
            return makeEnvironmentLight(std::move(*map), toWorld, SphereLayout::EqualArea);
        }
        // A uniform sky of radiance L lights an upward surface with pi L.
        const double illuminance = p.getFloat("illuminance", -1);
        return std::make_unique<InfiniteLight>(pbrt4Emission(p, "L") * (illuminance > 0 ? float(illuminance / M_PI) : 1.0f));
    }
    if (type == "goniometric") {
        noPower();
        return makeGoniometricLight(squareImage(), pbrt4Emission(p, "I"), toWorld, SphereLayout::EqualArea);
    }
    if (type == "projection") {
        noPower();
        const float fov = float(p.getFloat("fov", 90));
        if (!(fov > 0 && fov < 180)) p.fail("fov must lie in (0, 180) degrees");
        return makeProjectionLight(image(), pbrt4Emission(p, "I"), fov, toWorld);
    }
    p.fail("light \"" + type + "\" is not supported (point, spot, distant, infinite, goniometric, projection)");
}

}  // namespace

std::unique_ptr<Light> makeLight(const std::string& type, const ParamSet& p, const Transform& toWorld,
                                 SceneDialect dialect, const PathResolver& resolve, std::vector<std::string>& warnings) {
    if (dialect == SceneDialect::PbrtV4) {
        std::unique_ptr<Light> light = makePbrt4Light(type, p, toWorld, resolve, warnings);
        p.checkAllUsed(warnings, {"portal"});
        return light;
    }
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
        const SpotPlacement s = spotPlacement(p, toWorld);
        light = std::make_unique<SpotLight>(s.from, s.axis, scale * p.getRgb("I", {1, 1, 1}), s.cone, s.delta, SceneDialect::PbrtV3);
    } else if (type == "distant") {
        light = std::make_unique<DistantLight>(distantDirection(p, toWorld), scale * p.getRgb("L", {1, 1, 1}));
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
