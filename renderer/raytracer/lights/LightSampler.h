#pragma once
// Chooses which light to sample at a shading point, in proportion to each light's emitted power
// (the luminance of power(); pbrt-v3's "power" strategy), so that one bright light among many dim
// ones gets the samples it deserves. The choice's probability enters the MIS weights.
#include <memory>
#include <unordered_map>
#include <vector>

#include "lights/Light.h"
#include "sampling/PiecewiseConstant.h"

namespace lenslab {

class LightSampler {
public:
    // The lights must have their scene bounds set (power() of distant and infinite lights needs them)
    // and outlive the sampler. All powers zero: uniform.
    explicit LightSampler(const std::vector<std::unique_ptr<Light>>& lights);
    // nullptr when there are no lights; pmf receives the probability of the light returned.
    const Light* choose(float u, float& pmf) const;
    float probability(const Light& light) const;  // 0 for a light not in the list

private:
    const std::vector<std::unique_ptr<Light>>& lights_;
    PiecewiseConstant1D distribution_;
    std::unordered_map<const Light*, float> probabilities_;
};

}  // namespace lenslab
