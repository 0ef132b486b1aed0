#include "materials/SubsurfaceAlbedo.h"

#include <algorithm>
#include <cmath>

#include "materials/Fresnel.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {

// Walks still inside after this many scatterings count as absorbed: at the highest albedo a
// reflectance of 0.95 needs (0.9998 at eta 1.33) they would keep 0.04 of their weight, and they
// are under 1% of the walks.
constexpr int kMaxScatterings = 1 << 14;
constexpr int kTableSize = 256;

// The cosine, against the inward normal, of a direction refracted into the medium from diffuse
// light outside: cosine-distributed outside, kept with the probability 1 - F of entering.
float enteringCosine(float eta, Pcg32& rng) {
    for (;;) {
        const float cosOut = std::sqrt(rng.uniform());
        if (rng.uniform() < fresnelDielectric(cosOut, 1.0f, eta)) continue;
        const float sin2In = (1 - cosOut * cosOut) / (eta * eta);
        return std::sqrt(std::max(0.0f, 1 - sin2In));
    }
}

// The number of scatterings before the walk leaves the medium z < 0 (unit mean free path,
// isotropic), or kMaxScatterings.
int scatteringsBeforeEscape(float eta, Pcg32& rng) {
    double z = 0;
    float mu = -enteringCosine(eta, rng);  // direction's z component
    for (int n = 0; n < kMaxScatterings;) {
        const double step = rng.exponential();
        if (z + step * mu < 0) {
            z += step * mu;
            mu = 2 * rng.uniform() - 1;
            ++n;
            continue;
        }
        // At the boundary: out, or reflected back in (the flight starts afresh, being memoryless).
        if (rng.uniform() >= fresnelDielectric(-mu, 1.0f, eta)) return n;
        z = 0;
        mu = -mu;
    }
    return kMaxScatterings;
}

}  // namespace

float chiangSingleScatteringAlbedo(float reflectance) {
    const float a = std::clamp(reflectance, 0.0f, 1.0f);
    const float s = 4.09712f + 4.20863f * a - std::sqrt(9.59217f + 41.6808f * a + 17.7126f * a * a);
    return std::clamp(1 - s * s, 0.0f, 1.0f);
}

SubsurfaceAlbedoTable::SubsurfaceAlbedoTable(float eta, int walks) : escapes_(kMaxScatterings, 0.0f) {
    Pcg32 rng(0x5ab5u, std::uint64_t(eta * 1e4f));
    for (int i = 0; i < walks; ++i) {
        const int n = scatteringsBeforeEscape(eta, rng);
        if (n < kMaxScatterings) escapes_[n] += 1.0f / float(walks);
    }
    int longest = 0;
    for (int n = 0; n < kMaxScatterings; ++n)
        if (escapes_[n] > 0) longest = n;
    escapes_.resize(longest + 1);
    for (int i = 0; i < kTableSize; ++i) {
        const float s = float(i) / (kTableSize - 1);
        bySqrtAbsorption_.push_back(reflectance(1 - s * s));
    }
}

float SubsurfaceAlbedoTable::reflectance(float albedo) const {
    // The sum of escapes_[n] albedo^n as four series in albedo^4, whose chains of multiplications
    // the processor overlaps (one chain of up to 16,384 took a tenth of the table's time).
    const double a = albedo, a4 = a * a * a * a;
    double sum[4] = {0, 0, 0, 0}, power[4] = {1, a, a * a, a * a * a};
    const std::size_t n = escapes_.size();
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) {
            sum[k] += escapes_[i + k] * power[k];
            power[k] *= a4;
        }
    for (int k = 0; i < n; ++i, ++k) sum[0] += escapes_[i] * power[k];
    return float(sum[0] + sum[1] + sum[2] + sum[3]);
}

float SubsurfaceAlbedoTable::singleScatteringAlbedo(float reflectance) const {
    const std::vector<float>& r = bySqrtAbsorption_;  // decreasing from r[0], albedo 1
    const float target = std::clamp(reflectance, 0.0f, r.front());
    const auto below = std::lower_bound(r.begin(), r.end(), target, std::greater<float>());
    if (below == r.begin()) return 1;
    if (below == r.end()) return 0;
    const int i = int(below - r.begin());
    const float t = (r[i - 1] - target) / (r[i - 1] - r[i]);
    const float s = (float(i - 1) + t) / (kTableSize - 1);
    return 1 - s * s;
}

}  // namespace lenslab
