#include "lights/PointLight.h"

namespace lenslab {

bool PointLight::sample(Vec3f p, float, float, LightSample& s) const {
    const Vec3f d = position_ - p;
    s.distance = length(d);
    if (!(s.distance > 0)) return false;
    s.wi = d / s.distance;
    s.radiance = intensity_ * directionalScale(-s.wi) / (s.distance * s.distance);
    s.pdf = 1;
    s.delta = true;
    return !isBlack(s.radiance);
}

}  // namespace lenslab
