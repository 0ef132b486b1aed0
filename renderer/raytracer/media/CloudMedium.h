#pragma once
// pbrt-v4's procedural "cloud" medium: octaves of Perlin noise, their lookup point perturbed by the
// noise's gradient for wisps, thinning with height and filling in below y = 0.5, as a density in
// [0, 1] times sigma_a and sigma_s over the box p0..p1 in the medium's space. The density's bound
// makes sigma_a + sigma_s the majorant.
#include "media/TrackedBoxMedium.h"

namespace lenslab {

struct CloudShape {
    float density = 1;    // scales the noise before the clamp to [0, 1]
    float wispiness = 1;  // how far the gradient moves the lookup point
    float frequency = 5;  // of the first octave, per unit of the medium's space
};

class CloudMedium final : public TrackedBoxMedium {
public:
    CloudMedium(CloudShape shape, Vec3f sigmaA, Vec3f sigmaS, Vec3f p0, Vec3f p1, const Transform& mediumToWorld,
                HenyeyGreenstein phase);
    // At p in the medium's space; in [0, 1].
    float density(Vec3f p) const;

private:
    void coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const override;

    CloudShape shape_;
    Vec3f sigmaA_, sigmaS_, p0_, p1_;
};

}  // namespace lenslab
