#include "lights/LightSampler.h"

namespace lenslab {

namespace {

std::vector<float> powers(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<float> w;
    w.reserve(lights.size());
    for (const auto& light : lights) w.push_back(luminance(light->power()));
    return w;
}

}  // namespace

LightSampler::LightSampler(const std::vector<std::unique_ptr<Light>>& lights)
    : lights_(lights), distribution_(powers(lights)) {
    for (std::size_t i = 0; i < lights.size(); ++i) probabilities_[lights[i].get()] = distribution_.binProbability(i);
}

const Light* LightSampler::choose(float u, float& pmf) const {
    pmf = 0;
    if (lights_.empty()) return nullptr;
    return lights_[distribution_.sampleDiscrete(u, pmf)].get();
}

float LightSampler::probability(const Light& light) const {
    const auto it = probabilities_.find(&light);
    return it == probabilities_.end() ? 0.0f : it->second;
}

}  // namespace lenslab
