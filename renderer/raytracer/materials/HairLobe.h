#pragma once
// Hair fibre scattering as pbrt-v4 renders it: the near-field model of d'Eon, Francois, Hill,
// Letteri & Aubry, "An Energy-Conserving Hair Reflectance Model" (EGSR 2011), with the
// importance sampling and parameter mappings of Chiang, Bitterli, Tappan & Burley, "A Practical
// and Controllable Hair and Fur Model for Production Path Tracing" (EGSR 2016). Light leaves a
// rough dielectric cylinder after p = 0 (R), 1 (TT), 2 (TRT) internal paths, plus a residual
// for the rest; each path has a longitudinal lobe Mp (with a modified Bessel function,
// d'Eon 2011), an attenuation Ap (Fresnel and absorption inside) and an azimuthal lobe Np
// (a logistic trimmed to [-pi, pi], Chiang 2016). The cuticle scales tilt the lobes by alpha.
//
// Local frame (Bsdf.h's): x along the fibre, z the shading normal, y = z x x; the azimuth is
// measured in the y-z plane. h in [-1, 1]: where the ray crossed the fibre's width.
#include "materials/Bsdf.h"

namespace lenslab {

struct HairParams {
    float h = 0;        // offset across the fibre, -1..1
    float eta = 1.55f;  // index of the fibre's interior
    Vec3f sigmaA;       // absorption per fibre radius of path (a chord through the axis is 2)
    float betaM = 0.3f, betaN = 0.3f;  // longitudinal and azimuthal roughness, 0..1
    float alphaDeg = 2;  // cuticle scale tilt, degrees
};

class HairLobe final : public Lobe {
public:
    static constexpr int kPaths = 3;  // R, TT, TRT; the residual is path kPaths

    explicit HairLobe(const HairParams& params);
    unsigned type() const override { return kReflection | kTransmission; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;
    float pdf(Vec3f wo, Vec3f wi) const override;
    void evaluate(Vec3f wo, Vec3f wi, Vec3f& f, float& pdf) const override;
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    struct Outgoing;  // what f, pdf and sample share about wo
    Outgoing outgoing(Vec3f wo) const;
    // Mp * Np of each path toward wi: f weighs them by Ap, the pdf by Ap's shares.
    void pathLobes(const Outgoing& o, Vec3f wi, float (&mn)[kPaths + 1]) const;
    Vec3f fFrom(const Outgoing& o, Vec3f wi, const float (&mn)[kPaths + 1]) const;
    static float pdfFrom(const Outgoing& o, const float (&mn)[kPaths + 1]);

    float h_, eta_;
    float gammaO_;  // asin h: the azimuth, from the fibre's normal, at which the ray enters
    Vec3f sigmaA_;
    float v_[kPaths + 1];  // longitudinal variance per path
    float logNorm_[kPaths + 1];  // log of Mp's normalisation per path
    float s_;              // logistic scale of Np
    float invTrimmedMass_;  // 1 / the logistic's mass inside [-pi, pi]
    float sin2kAlpha_[kPaths], cos2kAlpha_[kPaths];
};

// Absorption from melanin concentrations, with the absorption coefficients of eumelanin and
// pheomelanin from d'Eon 2011, in linear sRGB, as pbrt-v4 uses them.
Vec3f hairSigmaAFromMelanin(float eumelanin, float pheomelanin);
// Absorption that gives a fibre of azimuthal roughness betaN roughly the multiple-scattered
// colour `reflectance` (Chiang 2016's fit), per channel; reflectance is clamped to (0, 1].
Vec3f hairSigmaAFromReflectance(Vec3f reflectance, float betaN);

}  // namespace lenslab
