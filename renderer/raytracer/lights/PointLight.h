#pragma once
// A light at one point radiating intensity I (W/sr), shaped per direction by subclasses: pbrt-v3's
// point light as it is, and the spot cone, goniometric diagram and projected image on top of it.
#include "lights/Light.h"

namespace lenslab {

class PointLight : public Light {
public:
    PointLight(Vec3f position, Vec3f intensity) : position_(position), intensity_(intensity) {}
    bool sample(Vec3f p, float u1, float u2, LightSample& s) const override;
    float pdf(Vec3f, Vec3f, const SurfaceHit*) const override { return 0; }  // no ray can hit a point
    Vec3f emitted(const SurfaceHit*, Vec3f) const override { return {}; }
    bool isDelta() const override { return true; }
    Vec3f power() const override { return 4.0f * float(M_PI) * intensity_; }

protected:
    // The factor on I along the unit world direction w leaving the light.
    virtual Vec3f directionalScale(Vec3f /*w*/) const { return {1, 1, 1}; }

    Vec3f position_, intensity_;
};

}  // namespace lenslab
