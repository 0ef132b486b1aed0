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
    // For long walks (subsurface volumes): the channel that draws the distance is chosen per event
    // in proportion to the path's throughput, and the event weighted by the mixture of the channels'
    // densities (one-sample MIS per event). A channel whose throughput grows is sampled more, so no
    // channel's weight runs away over hundreds of events, where the path-level hero weights leave
    // most paths to one channel (colour noise). The density does not depend on the path's hero,
    // whose throughput is hero-independent: pdfRatio is 1.
    // The distance is drawn first (infinite where nothing scatters), so that the caller traces its
    // ray only that far; walkEvent, with the same throughput, then gives the event for the surface
    // at tMax (t >= tMax: passed on to it).
    float walkDistance(Vec3f throughput, Pcg32& rng) const;
    MediumEvent walkEvent(float t, float tMax, Vec3f throughput) const;

private:
    float distance(int channel, Pcg32& rng) const;
    MediumEvent eventAt(float t, float tMax, Vec3f& pdf) const;
    MediumEvent absorbed(float tMax) const;

    Vec3f sigmaS_, sigmaT_;
};

}  // namespace lenslab
