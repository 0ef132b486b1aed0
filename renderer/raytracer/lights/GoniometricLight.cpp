// pbrt-v3's and pbrt-v4's goniometric light: a point light whose intensity a measured diagram
// scales. Both swap light-space y and z before mapping the direction into the diagram: pbrt-v3's
// columns run over phi and its rows over theta about +y, pbrt-v4's diagram is an equal-area square.
#include <cmath>

#include "lights/ImageLights.h"
#include "lights/PointLight.h"
#include "sampling/EqualAreaSphere.h"

namespace lenslab {

namespace {

class GoniometricLight : public PointLight {
public:
    GoniometricLight(LinearImage diagram, Vec3f intensity, const Transform& lightToWorld, SphereLayout layout)
        : PointLight(transformPoint(lightToWorld, {0, 0, 0}), intensity), diagram_(std::move(diagram)),
          toLight_(inverse(lightToWorld)), layout_(layout) {}
    Vec3f power() const override { return PointLight::power() * diagram_.average(); }

protected:
    Vec3f directionalScale(Vec3f w) const override {
        const Vec3f d = normalize(transformVector(toLight_, w));
        if (layout_ == SphereLayout::EqualArea) {
            float s, t;
            equalAreaSphereToSquare({d.x, d.z, d.y}, s, t);
            return diagram_.lookup(s, t);
        }
        float phi = std::atan2(d.z, d.x);  // y and z swapped: the pole is +y
        if (phi < 0) phi += 2.0f * float(M_PI);
        const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
        return diagram_.lookup(phi / (2.0f * float(M_PI)), theta / float(M_PI));
    }

private:
    LinearImage diagram_;
    Transform toLight_;
    SphereLayout layout_;
};

}  // namespace

std::unique_ptr<Light> makeGoniometricLight(std::optional<LinearImage> diagram, Vec3f intensity,
                                            const Transform& lightToWorld, SphereLayout layout) {
    if (!diagram) return std::make_unique<PointLight>(transformPoint(lightToWorld, {0, 0, 0}), intensity);
    return std::make_unique<GoniometricLight>(std::move(*diagram), intensity, lightToWorld, layout);
}

}  // namespace lenslab
