#pragma once
// From the colour a subsurface material should have (its diffuse reflectance) to the
// single-scattering albedo of the medium inside it, for pbrt-v4's "reflectance" + "mfp" form.
//
// The reflectance is that of a semi-infinite, isotropically scattering medium behind a smooth
// boundary of index eta, for the light that has entered it (diffuse light from outside, refracted
// in): the fraction that finds its way out again. It is tabulated per eta from random walks. Each
// walk runs without absorption and records how many times it scattered before it escaped, n; the
// reflectance at single-scattering albedo a is then the mean of a^n over the walks, for every a at
// once. pbrt-v4 inverts its photon-beam-diffusion profile's reflectance instead (docs/media.md).
#include <vector>

namespace lenslab {

// Chiang, Kutz & Burley, "Practical and Controllable Subsurface Scattering for Production Path
// Tracing" (SIGGRAPH 2016 talk): their fit of the single-scattering albedo that gives a random
// walk with an index-matched boundary the diffuse reflectance `reflectance`.
float chiangSingleScatteringAlbedo(float reflectance);

class SubsurfaceAlbedoTable {
public:
    // walks: the number of random walks (the default keeps the reflectance within about 0.004).
    explicit SubsurfaceAlbedoTable(float eta, int walks = 1 << 14);
    float reflectance(float singleScatteringAlbedo) const;
    // The inverse, for a reflectance in [0, 1] (clamped there).
    float singleScatteringAlbedo(float reflectance) const;

private:
    // The reflectance at albedo 1 - s^2 for s = i / (n - 1): about linear in s near albedo 1.
    std::vector<float> bySqrtAbsorption_;
    std::vector<float> escapes_;  // walks escaping after n scatterings, over all walks
};

}  // namespace lenslab
