#include "media/CloudMedium.h"

#include <algorithm>

#include "sampling/Noise.h"

namespace lenslab {

CloudMedium::CloudMedium(CloudShape shape, Vec3f sigmaA, Vec3f sigmaS, Vec3f p0, Vec3f p1, const Transform& mediumToWorld,
                         HenyeyGreenstein phase)
    : TrackedBoxMedium(mediumToWorld * translate(p0.x, p0.y, p0.z) * scale(p1.x - p0.x, p1.y - p0.y, p1.z - p0.z),
                       MajorantGrid::uniform(maxComponent(sigmaA + sigmaS)), phase),
      shape_(shape), sigmaA_(sigmaA), sigmaS_(sigmaS), p0_(p0), p1_(p1) {}

float CloudMedium::density(Vec3f p) const {
    Vec3f q = shape_.frequency * p;
    // Two octaves of the gradient displace the lookup: the noise's smooth blobs turn into wisps.
    float displacement = 0.05f * shape_.wispiness, frequency = 10;
    for (int i = 0; i < 2 && shape_.wispiness > 0; ++i) {
        q += displacement * perlinNoiseGradient(frequency * q);
        displacement *= 0.5f;
        frequency *= 1.99f;
    }
    const float noise = 0.5f * fractionalBrownianMotion(q, 0.5f, 5);
    // Thinner with height; below y = 0.5 a floor of solid cloud.
    const float d = std::clamp((1 - p.y) * 4.5f * shape_.density * noise, 0.0f, 1.0f);
    return std::clamp(d + 2 * std::max(0.0f, 0.5f - p.y), 0.0f, 1.0f);
}

void CloudMedium::coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const {
    const float d = density(p0_ + pBox * (p1_ - p0_));
    sigmaA = d * sigmaA_;
    sigmaS = d * sigmaS_;
}

}  // namespace lenslab
