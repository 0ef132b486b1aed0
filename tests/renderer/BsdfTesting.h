#pragma once
// Helpers for material tests: a material from scene text, the surface it is hit on, and the
// statistics of its sampling (directional albedo, histograms of sampled directions).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "materials/Material.h"
#include "sampling/Sampling.h"
#include "scene/SceneDescription.h"
#include "TestScenes.h"

namespace lenslab::test {

// The material `directive` (a Material or NamedMaterial line, after any MakeNamedMaterial or
// Texture lines) as the parser builds it, from a scene written into `dir`.
inline std::shared_ptr<const Material> parseMaterial(const TempDir& dir, const std::string& directive) {
    const std::string scene = dir.write("material.pbrt",
                                        "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 4 "
                                        "\"integer yresolution\" 4\nWorldBegin\n" + directive +
                                            "\nShape \"sphere\"\nWorldEnd\n");
    return parseSceneFile(scene).shapes.at(0).material;
}

// A hit on the plane z = 0 with normal +z, tangent +x.
inline SurfaceHit flatHit() {
    SurfaceHit h;
    h.ng = h.ns = {0, 0, 1};
    h.dpdu = {1, 0, 0};
    return h;
}

inline Vec3f direction(float thetaDeg, float phiDeg) {
    const float t = thetaDeg * float(M_PI) / 180, p = phiDeg * float(M_PI) / 180;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

struct AlbedoEstimate {
    Vec3f mean, stderr3;  // mean weight per channel and three standard errors
};

inline AlbedoEstimate summarise(Vec3f sum, Vec3f sum2, int n) {
    const Vec3f mean = sum / float(n), var = sum2 / float(n) - mean * mean;
    const auto se = [&](float v) { return 3.0f * std::sqrt(std::max(0.0f, v) / float(n)); };
    return {mean, {se(var.x), se(var.y), se(var.z)}};
}

// Directional albedo: the mean of sample weights (lost samples count as zero), with every lobe.
// etaBelow: the index of refraction below the surface (above is 1): radiance crossing a boundary
// changes by the squared ratio of the indices, which this undoes to count energy.
inline AlbedoEstimate sampledAlbedo(const Material& m, Vec3f wo, int n, std::uint64_t seed = 1, float etaBelow = 1) {
    const SurfaceHit h = flatHit();
    Pcg32 rng(seed);
    Vec3f sum{}, sum2{};
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        const float a = rng.uniform(), b = rng.uniform(), c = rng.uniform();
        if (!m.sample(h, wo, a, b, c, s)) continue;
        if (s.wi.z * wo.z < 0) s.weight = s.weight * (s.wi.z < 0 ? etaBelow * etaBelow : 1 / (etaBelow * etaBelow));
        sum += s.weight;
        sum2 += s.weight * s.weight;
    }
    return summarise(sum, sum2, n);
}

// The same integral from evaluate() alone: uniform directions over the sphere, f |cos| / (1/4 pi).
inline AlbedoEstimate evaluatedAlbedo(const Material& m, Vec3f wo, int n, std::uint64_t seed = 2) {
    const SurfaceHit h = flatHit();
    Pcg32 rng(seed);
    Vec3f sum{}, sum2{};
    for (int i = 0; i < n; ++i) {
        const float a = rng.uniform(), b = rng.uniform();
        const Vec3f v = 4.0f * float(M_PI) * m.evaluate(h, wo, uniformSphere(a, b));
        sum += v;
        sum2 += v * v;
    }
    return summarise(sum, sum2, n);
}

// Sampled directions binned on the sphere (cells equal in solid angle: uniform in cos(theta) and
// phi) against the counts pdf() predicts, for the non-specular samples.
struct HistogramTest {
    double chi2 = 0;
    int dof = 0;
    double pdfIntegral = 0;    // integral of pdf() over the sphere
    double sampledShare = 0;   // fraction of draws that gave a non-specular direction
};

inline HistogramTest histogramTest(const Material& m, Vec3f wo, int n, std::uint64_t seed = 3) {
    constexpr int kTheta = 20, kPhi = 40, kSub = 10;
    const SurfaceHit h = flatHit();
    const auto cellOf = [&](Vec3f w) {
        const int i = std::clamp(int((w.z + 1.0f) * 0.5f * kTheta), 0, kTheta - 1);
        float phi = std::atan2(w.y, w.x);
        if (phi < 0) phi += 2.0f * float(M_PI);
        const int j = std::clamp(int(phi / (2.0f * float(M_PI)) * kPhi), 0, kPhi - 1);
        return i * kPhi + j;
    };
    std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
    Pcg32 rng(seed);
    int hits = 0;
    for (int k = 0; k < n; ++k) {
        BsdfSample s;
        const float a = rng.uniform(), b = rng.uniform(), c = rng.uniform();
        if (!m.sample(h, wo, a, b, c, s) || s.specular) continue;
        observed[cellOf(s.wi)] += 1;
        ++hits;
    }
    HistogramTest t;
    const double cellArea = 4.0 * M_PI / (kTheta * kPhi) / (kSub * kSub);
    for (int i = 0; i < kTheta; ++i)
        for (int j = 0; j < kPhi; ++j)
            for (int a = 0; a < kSub; ++a)
                for (int b = 0; b < kSub; ++b) {
                    const double z = -1.0 + 2.0 * (i + (a + 0.5) / kSub) / kTheta;
                    const double phi = 2.0 * M_PI * (j + (b + 0.5) / kSub) / kPhi;
                    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    const Vec3f w{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)};
                    const double p = m.pdf(h, wo, w) * cellArea;
                    expected[i * kPhi + j] += p * n;
                    t.pdfIntegral += p;
                }
    // Cells expecting fewer than 5 samples are pooled, as the chi-square approximation needs.
    double pooledObserved = 0, pooledExpected = 0;
    for (std::size_t c = 0; c < observed.size(); ++c) {
        if (expected[c] < 5) {
            pooledObserved += observed[c];
            pooledExpected += expected[c];
            continue;
        }
        t.chi2 += (observed[c] - expected[c]) * (observed[c] - expected[c]) / expected[c];
        ++t.dof;
    }
    if (pooledExpected >= 5) {
        t.chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++t.dof;
    } else {
        t.chi2 += pooledObserved > 5 + 3 * pooledExpected ? 1e9 : 0;  // samples where pdf says none
    }
    t.dof = std::max(1, t.dof - 1);
    t.sampledShare = double(hits) / n;
    return t;
}

// A generous acceptance bound for chi-square with `dof` degrees of freedom (about 5 sigma).
inline double chi2Bound(int dof) { return dof + 5.0 * std::sqrt(2.0 * dof) + 10.0; }

}  // namespace lenslab::test
