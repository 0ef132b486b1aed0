#pragma once
// A medium with the same coefficients everywhere: distances and transmittance in closed form.
#include "media/ParticipatingMedium.h"

namespace lenslab {

class HomogeneousMedium final : public ParticipatingMedium {
public:
    HomogeneousMedium(Vec3f sigmaA, Vec3f sigmaS, HenyeyGreenstein phase)
        : ParticipatingMedium(phase), sigmaS_(sigmaS), sigmaT_(sigmaA + sigmaS) {}
    MediumEvent sample(Vec3f o, Vec3f d, float tMax, int hero, Pcg32& rng) const override;
    Vec3f transmittance(Vec3f o, Vec3f d, float tMax, Pcg32& rng) const override;

private:
    Vec3f sigmaS_, sigmaT_;
};

}  // namespace lenslab
