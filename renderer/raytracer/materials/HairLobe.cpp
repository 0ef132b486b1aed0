#include "materials/HairLobe.h"

#include <algorithm>
#include <cmath>

#include "core/Pi.h"
#include "materials/Fresnel.h"

namespace lenslab {

namespace {

float sq(float x) { return x * x; }
float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safeAsin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }

// Modified Bessel function of the first kind, order 0: its power series, enough terms for the
// arguments below 12 where it is used directly.
float besselI0(float x) {
    float sum = 0, term = 1;
    const float x2 = x * x / 4;
    for (int i = 1; i <= 11; ++i) {
        sum += term;
        term *= x2 / float(i * i);
    }
    return sum;
}

// log I0 beyond 12, by its asymptotic expansion (I0 itself overflows a float from about 90).
float logBesselI0(float x) { return x + 0.5f * (-std::log(2 * kPif) + std::log(1 / x) + 1 / (8 * x)); }

// d'Eon 2011's longitudinal lobe, csch(1/v) / (2v) exp(-sin_i sin_o / v) I0(cos_i cos_o / v), with
// the normalisation in logarithms (csch(1/v) underflows for narrow lobes); logNorm: log(csch(1/v) /
// (2v)), fixed per lobe. I0 is taken directly where its series holds (below 12, where it is at
// most 2e4, so that exp underflowing alone loses nothing), in logarithms beyond.
float longitudinal(float cosI, float cosO, float sinI, float sinO, float v, float logNorm) {
    const float x = cosI * cosO / v, rest = logNorm - sinI * sinO / v;
    if (x > 12) return std::exp(logBesselI0(x) + rest);
    return besselI0(x) * std::exp(rest);
}

// csch(1/v) / (2v) = exp(-1/v) / (v (1 - exp(-2/v))).
float longitudinalLogNorm(float v) { return -1 / v - std::log(v) - std::log1p(-std::exp(-2 / v)); }

float logistic(float x, float s) {
    const float e = std::exp(-std::fabs(x) / s);
    return e / (s * sq(1 + e));
}
float logisticCdf(float x, float s) { return 1 / (1 + std::exp(-x / s)); }

// Chiang 2016's azimuthal lobe: a logistic around the path's exit azimuth, trimmed to [-pi, pi]
// (the logistic's mass inside, 1 - 2 cdf(-pi), is divided out).
float trimmedMass(float s) { return logisticCdf(kPif, s) - logisticCdf(-kPif, s); }
float sampleTrimmedLogistic(float u, float s) {
    const float x = -s * std::log(1 / (u * trimmedMass(s) + logisticCdf(-kPif, s)) - 1);
    return std::clamp(x, -kPif, kPif);
}

// The azimuth at which path p leaves, relative to the incoming one (d'Eon 2011).
float exitAzimuth(int p, float gammaO, float gammaT) { return 2 * float(p) * gammaT - 2 * gammaO + float(p) * kPif; }

float azimuthal(float phi, int p, float s, float gammaO, float gammaT) {
    const float d = std::remainder(phi - exitAzimuth(p, gammaO, gammaT), 2 * kPif);  // into [-pi, pi]
    return logistic(d, s);  // untrimmed: the callers divide by the trimmed mass
}

float average(Vec3f c) { return (c.x + c.y + c.z) / 3; }

Vec3f expNeg(Vec3f a) { return {std::exp(-a.x), std::exp(-a.y), std::exp(-a.z)}; }

}  // namespace

struct HairLobe::Outgoing {
    float sinTheta, cosTheta, phi, gammaO, gammaT;
    // The outgoing elevation tilted by the cuticle for each path (the residual is not tilted).
    float sinThetaP[kPaths + 1], cosThetaP[kPaths + 1];
    Vec3f ap[kPaths + 1];  // attenuation per path
    float apShare[kPaths + 1];  // the paths' shares of the attenuation, for sampling
};

HairLobe::HairLobe(const HairParams& q) : h_(q.h), eta_(q.eta), gammaO_(safeAsin(q.h)), sigmaA_(q.sigmaA) {
    // Chiang 2016's fits: roughness to longitudinal variance and logistic scale.
    const float bm = q.betaM, bn = q.betaN;
    v_[0] = sq(0.726f * bm + 0.812f * sq(bm) + 3.7f * std::pow(bm, 20.0f));
    v_[1] = 0.25f * v_[0];
    v_[2] = 4 * v_[0];
    v_[3] = v_[2];
    s_ = std::sqrt(kPif / 8) * (0.265f * bn + 1.194f * sq(bn) + 5.372f * std::pow(bn, 22.0f));
    for (int p = 0; p <= kPaths; ++p) logNorm_[p] = longitudinalLogNorm(v_[p]);
    invTrimmedMass_ = 1 / trimmedMass(s_);
    // sin and cos of 2^k alpha by doubling.
    sin2kAlpha_[0] = std::sin(q.alphaDeg * kPif / 180);
    cos2kAlpha_[0] = safeSqrt(1 - sq(sin2kAlpha_[0]));
    for (int k = 1; k < kPaths; ++k) {
        sin2kAlpha_[k] = 2 * cos2kAlpha_[k - 1] * sin2kAlpha_[k - 1];
        cos2kAlpha_[k] = sq(cos2kAlpha_[k - 1]) - sq(sin2kAlpha_[k - 1]);
    }
}

HairLobe::Outgoing HairLobe::outgoing(Vec3f wo) const {
    Outgoing o;
    o.sinTheta = std::clamp(wo.x, -1.0f, 1.0f);
    o.cosTheta = safeSqrt(1 - sq(o.sinTheta));
    o.phi = std::atan2(wo.z, wo.y);
    o.gammaO = gammaO_;
    // Inside the fibre: the refracted elevation, and the modified index (Bravais) for the azimuth.
    const float sinThetaT = o.sinTheta / eta_, cosThetaT = safeSqrt(1 - sq(sinThetaT));
    const float etaP = safeSqrt(sq(eta_) - sq(o.sinTheta)) / std::max(o.cosTheta, 1e-6f);
    const float sinGammaT = h_ / etaP, cosGammaT = safeSqrt(1 - sq(sinGammaT));
    o.gammaT = safeAsin(sinGammaT);
    const Vec3f t = expNeg(sigmaA_ * (2 * cosGammaT / std::max(cosThetaT, 1e-6f)));  // one chord

    // Cuticle tilts (Chiang 2016): R by -2 alpha, TT by alpha, TRT by 4 alpha.
    const auto tilt = [&](int p, float sinA, float cosA) {
        o.sinThetaP[p] = o.sinTheta * cosA + o.cosTheta * sinA;
        o.cosThetaP[p] = std::fabs(o.cosTheta * cosA - o.sinTheta * sinA);
    };
    tilt(0, -sin2kAlpha_[1], cos2kAlpha_[1]);
    tilt(1, sin2kAlpha_[0], cos2kAlpha_[0]);
    tilt(2, sin2kAlpha_[2], cos2kAlpha_[2]);
    tilt(3, 0, 1);

    // Attenuation: Fresnel at the entry point, the chord's transmittance per internal pass, and
    // the geometric series of all longer paths in the residual.
    const float f = fresnelDielectric(o.cosTheta * safeSqrt(1 - sq(h_)), 1, eta_);
    o.ap[0] = Vec3f{f, f, f};
    o.ap[1] = sq(1 - f) * t;
    o.ap[2] = o.ap[1] * t * f;
    const Vec3f tf = f * t;
    o.ap[3] = o.ap[2] * tf * Vec3f{1 / (1 - tf.x), 1 / (1 - tf.y), 1 / (1 - tf.z)};
    float total = 0;
    for (const Vec3f& a : o.ap) total += average(a);
    for (int p = 0; p <= kPaths; ++p) o.apShare[p] = total > 0 ? average(o.ap[p]) / total : 0;
    return o;
}

void HairLobe::pathLobes(const Outgoing& o, Vec3f wi, float (&mn)[kPaths + 1]) const {
    const float sinThetaI = std::clamp(wi.x, -1.0f, 1.0f), cosThetaI = safeSqrt(1 - sq(sinThetaI));
    const float phi = std::atan2(wi.z, wi.y) - o.phi;
    for (int p = 0; p < kPaths; ++p)
        mn[p] = longitudinal(cosThetaI, o.cosThetaP[p], sinThetaI, o.sinThetaP[p], v_[p], logNorm_[p]) *
                (azimuthal(phi, p, s_, o.gammaO, o.gammaT) * invTrimmedMass_);
    mn[kPaths] =
        longitudinal(cosThetaI, o.cosThetaP[kPaths], sinThetaI, o.sinThetaP[kPaths], v_[kPaths], logNorm_[kPaths]) /
        (2 * kPif);
}

// The lobes are already a density per solid angle (Mp is normalised against cos theta_i dtheta_i,
// Np against dphi): f divides out the normal's cosine the integrator multiplies in.
Vec3f HairLobe::fFrom(const Outgoing& o, Vec3f wi, const float (&mn)[kPaths + 1]) const {
    const float c = std::fabs(wi.z);
    if (!(c > 0)) return {};
    Vec3f sum{};
    for (int p = 0; p <= kPaths; ++p) sum += mn[p] * o.ap[p];
    return sum / c;
}

float HairLobe::pdfFrom(const Outgoing& o, const float (&mn)[kPaths + 1]) {
    float sum = 0;
    for (int p = 0; p <= kPaths; ++p) sum += mn[p] * o.apShare[p];
    return sum;
}

// f and pdf alone cost what both together do (the per-path lobes), and are rarely asked for alone.
Vec3f HairLobe::f(Vec3f wo, Vec3f wi) const {
    Vec3f value;
    float density;
    evaluate(wo, wi, value, density);
    return value;
}

float HairLobe::pdf(Vec3f wo, Vec3f wi) const {
    Vec3f value;
    float density;
    evaluate(wo, wi, value, density);
    return density;
}

void HairLobe::evaluate(Vec3f wo, Vec3f wi, Vec3f& f, float& pdf) const {
    const Outgoing o = outgoing(wo);
    float mn[kPaths + 1];
    pathLobes(o, wi, mn);
    f = fFrom(o, wi, mn);
    pdf = pdfFrom(o, mn);
}

bool HairLobe::sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const {
    const Outgoing o = outgoing(wo);
    // Choose a path by its share of the attenuation, then reuse uc's remainder for the azimuth.
    int p = 0;
    float below = 0;
    while (p < kPaths && uc >= below + o.apShare[p]) below += o.apShare[p++];
    if (!(o.apShare[p] > 0)) return false;
    uc = std::min((uc - below) / o.apShare[p], 0x1.fffffep-1f);

    // Elevation: Mp sampled exactly (d'Eon 2011's lobe around the tilted specular elevation).
    const float v = v_[p];
    const float cosT = 1 + v * std::log(std::max(u1, 1e-5f) + (1 - u1) * std::exp(-2 / v));
    const float sinT = safeSqrt(1 - sq(cosT));
    const float sinThetaI = -cosT * o.sinThetaP[p] + sinT * std::cos(2 * kPif * u2) * o.cosThetaP[p];
    const float cosThetaI = safeSqrt(1 - sq(sinThetaI));
    const float dphi = p < kPaths ? exitAzimuth(p, o.gammaO, o.gammaT) + sampleTrimmedLogistic(uc, s_) : 2 * kPif * uc;
    const float phiI = o.phi + dphi;
    out.wi = {sinThetaI, cosThetaI * std::cos(phiI), cosThetaI * std::sin(phiI)};
    float mn[kPaths + 1];
    pathLobes(o, out.wi, mn);
    out.pdf = pdfFrom(o, mn);
    out.f = fFrom(o, out.wi, mn);
    out.specular = false;
    return out.pdf > 0;
}

Vec3f hairSigmaAFromMelanin(float eumelanin, float pheomelanin) {
    return eumelanin * Vec3f{0.419f, 0.697f, 1.37f} + pheomelanin * Vec3f{0.187f, 0.4f, 1.05f};
}

Vec3f hairSigmaAFromReflectance(Vec3f c, float bn) {
    const float d = 5.969f - 0.215f * bn + 2.532f * sq(bn) - 10.73f * std::pow(bn, 3.0f) + 5.574f * std::pow(bn, 4.0f) +
                    0.245f * std::pow(bn, 5.0f);
    const auto one = [&](float r) { return sq(std::log(std::clamp(r, 1e-4f, 1.0f)) / d); };
    return {one(c.x), one(c.y), one(c.z)};
}

}  // namespace lenslab
