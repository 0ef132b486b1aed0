// pbrt-v3's goniometric light: a point light whose intensity a measured diagram scales. The
// diagram's columns run over phi and its rows over theta, both about light-space +y (pbrt-v3
// swaps y and z before taking spherical angles).
#include <cmath>

#include "lights/ImageLights.h"
#include "lights/PointLight.h"

namespace lenslab {

namespace {

class GoniometricLight : public PointLight {
public:
    GoniometricLight(LinearImage diagram, Vec3f intensity, const Transform& lightToWorld)
        : PointLight(transformPoint(lightToWorld, {0, 0, 0}), intensity), diagram_(std::move(diagram)),
          toLight_(inverse(lightToWorld)) {}
    Vec3f power() const override { return PointLight::power() * diagram_.average(); }

protected:
    Vec3f directionalScale(Vec3f w) const override {
        const Vec3f d = normalize(transformVector(toLight_, w));
        float phi = std::atan2(d.z, d.x);  // y and z swapped: the pole is +y
        if (phi < 0) phi += 2.0f * float(M_PI);
        const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
        return diagram_.lookup(phi / (2.0f * float(M_PI)), theta / float(M_PI));
    }

private:
    LinearImage diagram_;
    Transform toLight_;
};

}  // namespace

std::unique_ptr<Light> makeGoniometricLight(std::optional<LinearImage> diagram, Vec3f intensity,
                                            const Transform& lightToWorld) {
    if (!diagram) return std::make_unique<PointLight>(transformPoint(lightToWorld, {0, 0, 0}), intensity);
    return std::make_unique<GoniometricLight>(std::move(*diagram), intensity, lightToWorld);
}

}  // namespace lenslab
