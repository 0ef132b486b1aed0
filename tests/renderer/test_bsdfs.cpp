// Every material's BSDF against the properties any BSDF must have (energy conservation,
// reciprocity, sampling that matches evaluation, a normalised pdf) and the closed forms it is built
// from (Fresnel equations, microfacet normalisation, Oren-Nayar, smooth limits of rough lobes).
#include <gtest/gtest.h>

#include <complex>

#include "BsdfTesting.h"
#include "materials/Bsdf.h"
#include "materials/DiffuseLobes.h"
#include "materials/Fresnel.h"
#include "materials/MetalSpectra.h"
#include "materials/Microfacet.h"

namespace lenslab {
namespace {

struct BsdfCase {
    const char* name;
    std::string directive;
    bool reciprocal;  // reflection only (transmission has its own relation, tested separately)
    float etaBelow = 1;  // a dielectric boundary's inner index, for counting energy
};

const char* kRough = " \"bool remaproughness\" \"false\"";

std::vector<BsdfCase> cases() {
    const std::string r = kRough;
    return {
        {"matte", "Material \"matte\" \"rgb Kd\" [1 1 1]", true},
        {"oren-nayar", "Material \"matte\" \"rgb Kd\" [1 1 1] \"float sigma\" 30", true},
        {"plastic", "Material \"plastic\" \"rgb Kd\" [0.5 0.5 0.5] \"rgb Ks\" [0.5 0.5 0.5] \"float roughness\" 0.3" + r, true},
        {"metal", "Material \"metal\" \"float roughness\" 0.3" + r, true},
        {"metal-anisotropic", "Material \"metal\" \"float uroughness\" 0.15 \"float vroughness\" 0.5 "
                              "\"spectrum eta\" \"metal-Al-eta\" \"spectrum k\" \"metal-Al-k\"" + r, true},
        {"metal-beckmann", "Material \"metal\" \"float uroughness\" 0.2 \"float vroughness\" 0.4 "
                           "\"string distribution\" \"beckmann\"" + r, true},
        {"rough-glass", "Material \"glass\" \"float uroughness\" 0.3 \"float vroughness\" 0.3" + r, false, 1.5f},
        {"rough-glass-beckmann", "Material \"glass\" \"float uroughness\" 0.25 \"float vroughness\" 0.4 "
                                 "\"string distribution\" \"beckmann\"" + r, false, 1.5f},
        {"substrate", "Material \"substrate\" \"rgb Kd\" [1 1 1] \"rgb Ks\" [0.05 0.05 0.05] "
                      "\"float uroughness\" 0.2 \"float vroughness\" 0.4" + r, true},
        {"uber", "Material \"uber\" \"rgb Kd\" [0.4 0.4 0.4] \"rgb Ks\" [0.3 0.3 0.3] \"rgb Kr\" [0.2 0.2 0.2] "
                 "\"float roughness\" 0.3" + r, true},
        {"translucent", "Material \"translucent\" \"rgb Kd\" [0.5 0.5 0.5] \"rgb Ks\" [0.5 0.5 0.5] "
                        "\"float roughness\" 0.3" + r, false},
        {"mix", "MakeNamedMaterial \"a\" \"string type\" \"matte\" \"rgb Kd\" [1 1 1]\n"
                "MakeNamedMaterial \"b\" \"string type\" \"metal\" \"float roughness\" 0.2" + r + "\n"
                "Material \"mix\" \"string namedmaterial1\" \"a\" \"string namedmaterial2\" \"b\" \"rgb amount\" [0.2 0.5 0.8]",
         true},
        {"smooth-glass", "Material \"glass\"", false, 1.5f},
        {"mirror", "Material \"mirror\" \"rgb Kr\" [1 1 1]", false},
    };
}

// Incident directions from normal to grazing, on both sides (the second side is the inside of
// glass), at an azimuth that is no symmetry axis of the anisotropic lobes.
const float kThetas[] = {0, 30, 60, 80, 89, 150, 175};

TEST(Bsdfs, WhiteFurnaceNoMaterialCreatesEnergy) {
    test::TempDir dir;
    for (const BsdfCase& c : cases()) {
        const auto m = test::parseMaterial(dir, c.directive);
        for (float theta : kThetas) {
            const auto a = test::sampledAlbedo(*m, test::direction(theta, 20), 30000, 1, c.etaBelow);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_LE(a.mean[ch], 1.0f + a.stderr3[ch] + 1e-3f)
                    << c.name << " theta " << theta << " channel " << ch << " albedo " << a.mean[ch];
        }
    }
}

TEST(Bsdfs, LambertAlbedoIsKdAtEveryAngle) {
    test::TempDir dir;
    const auto m = test::parseMaterial(dir, "Material \"matte\" \"rgb Kd\" [0.8 0.5 0.2]");
    for (float theta : {0.0f, 45.0f, 89.0f}) {
        const auto a = test::sampledAlbedo(*m, test::direction(theta, 0), 1000);
        EXPECT_NEAR(a.mean.x, 0.8f, 1e-5f);  // cosine sampling: every weight is Kd exactly
        EXPECT_NEAR(a.mean.z, 0.2f, 1e-5f);
    }
}

// The mean sample weight and the integral of evaluate() are two estimates of one albedo: a wrong
// factor in sample(), pdf() or evaluate() sets them apart.
TEST(Bsdfs, SampleWeightsAgreeWithEvaluation) {
    test::TempDir dir;
    for (const BsdfCase& c : cases()) {
        const auto m = test::parseMaterial(dir, c.directive);
        if (m->isSpecular()) continue;
        for (float theta : {10.0f, 50.0f, 75.0f, 140.0f}) {
            const Vec3f wo = test::direction(theta, 20);
            const auto s = test::sampledAlbedo(*m, wo, 40000);
            const auto e = test::evaluatedAlbedo(*m, wo, 100000);
            // Specular lobes carry energy that evaluate() cannot see: uber's Kr.
            const float specularShare = c.name == std::string("uber") ? 1.0f : 0.0f;
            for (int ch = 0; ch < 3; ++ch) {
                if (specularShare > 0) {
                    EXPECT_GE(s.mean[ch], e.mean[ch] - s.stderr3[ch] - e.stderr3[ch]) << c.name;
                    continue;
                }
                EXPECT_NEAR(s.mean[ch], e.mean[ch], s.stderr3[ch] + e.stderr3[ch] + 2e-3f)
                    << c.name << " theta " << theta << " channel " << ch;
            }
        }
    }
}

// A BSDF sample takes its own lobe's f and pdf from the lobe's sample and evaluates only the other
// lobes at the sampled direction: its pdf and weight must be the whole mixture's evaluation there
// (Material::pdf and evaluate), pointwise. Hair (one lobe sharing its work between f and pdf) and
// uber (a mirror lobe beside the rough ones) included.
// Also where the shading normal leans 25 degrees off the geometric one (bump maps, interpolated
// normals): there a lobe can send light to the geometric side its type does not scatter to, and
// the mixture's pdf must still count it, as sampling drew it.
TEST(Bsdfs, SampleWeightsAreTheMixturesEvaluationAtTheSample) {
    test::TempDir dir;
    std::vector<BsdfCase> all = cases();
    all.push_back({"hair", "Material \"hair\" \"float eumelanin\" 1.3 \"float beta_m\" 0.25", false});
    // Float rounding: the leaning frame's own turns, amplified at a sharp lobe's peak (pdf ~300), reach
    // 3e-4 of the pdf; a lobe left out of the mixture is 1% or more of it.
    const auto near = [](float a, float b, float relative) {
        return std::fabs(a - b) <= relative * std::max(std::fabs(a), std::fabs(b)) + 1e-12f;
    };
    SurfaceHit flat = test::flatHit();
    flat.v = 0.3f;  // the hair's offset across the fibre
    SurfaceHit leaning = test::flatHit();
    leaning.ns = {0, std::sin(25 * float(M_PI) / 180), std::cos(25 * float(M_PI) / 180)};
    Pcg32 rng(11);
    for (const BsdfCase& c : all) {
        for (const bool lean : {false, true}) {
            if (lean && std::string(c.name) == "hair") continue;  // a fibre has no shading normal
            const SurfaceHit& h = lean ? leaning : flat;
            const auto m = test::parseMaterial(dir, c.directive);
            const Bsdf bsdf(h, *m);
            int checked = 0;
            for (int i = 0; i < 300; ++i) {
                const Vec3f wo = uniformSphere(rng.uniform(), rng.uniform());
                BsdfSample s;
                if (!bsdf.sample(wo, rng.uniform(), rng.uniform(), rng.uniform(), s) || s.specular) continue;
                const float pm = m->pdf(h, wo, s.wi);
                const Vec3f wm = m->evaluate(h, wo, s.wi) / pm;
                const float relative = lean ? 1e-3f : 1e-5f;
                EXPECT_TRUE(near(s.pdf, pm, relative)) << c.name << (lean ? ", leaning" : "") << ": sampled pdf " << s.pdf << " against " << pm;
                EXPECT_TRUE(near(s.weight.x, wm.x, relative) && near(s.weight.z, wm.z, relative))
                    << c.name << (lean ? ", leaning" : "") << ": weight " << s.weight.x << " against " << wm.x;
                ++checked;
            }
            if (!m->isSpecular()) {
                EXPECT_GT(checked, 100) << c.name;
            }
        }
    }
}

TEST(Bsdfs, SampledDirectionsFollowThePdf) {
    test::TempDir dir;
    for (const BsdfCase& c : cases()) {
        const auto m = test::parseMaterial(dir, c.directive);
        if (m->isSpecular()) continue;
        for (float theta : {30.0f, 75.0f, 160.0f}) {
            const auto t = test::histogramTest(*m, test::direction(theta, 20), 100000);
            EXPECT_LT(t.chi2, test::chi2Bound(t.dof)) << c.name << " theta " << theta << " dof " << t.dof;
            // The pdf integrates to the share of draws it describes (lobes may lose samples below
            // the horizon, and uber's mirror lobe has no density).
            EXPECT_NEAR(t.pdfIntegral, t.sampledShare, 0.01) << c.name << " theta " << theta;
        }
    }
}

TEST(Bsdfs, PdfOfDiffuseLobesIntegratesToOne) {
    test::TempDir dir;
    for (const char* d : {"Material \"matte\"", "Material \"matte\" \"float sigma\" 40"}) {
        const auto t = test::histogramTest(*test::parseMaterial(dir, d), test::direction(40, 0), 1000);
        EXPECT_NEAR(t.pdfIntegral, 1.0, 2e-3) << d;
        EXPECT_EQ(t.sampledShare, 1.0) << d;
    }
}

TEST(Bsdfs, ReflectionIsReciprocal) {
    test::TempDir dir;
    const SurfaceHit h = test::flatHit();
    Pcg32 rng(7);
    for (const BsdfCase& c : cases()) {
        if (!c.reciprocal) continue;
        const auto m = test::parseMaterial(dir, c.directive);
        for (int i = 0; i < 200; ++i) {
            const Vec3f a = cosineHemisphere(rng.uniform(), rng.uniform());
            const Vec3f b = cosineHemisphere(rng.uniform(), rng.uniform());
            const Vec3f fab = m->evaluate(h, a, b) / b.z, fba = m->evaluate(h, b, a) / a.z;
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(fab[ch], fba[ch], 1e-4f * std::max(1.0f, fab[ch])) << c.name;
        }
    }
}

// Radiance crossing a boundary: f(wi -> wo) = (eta_i / eta_o)^2 f(wo -> wi), eta_i being the
// index on wi's side.
TEST(Bsdfs, RoughTransmissionObeysTheEtaSquaredReciprocity) {
    test::TempDir dir;
    const auto m = test::parseMaterial(dir, "Material \"glass\" \"float eta\" 1.5 \"float uroughness\" 0.4 "
                                            "\"float vroughness\" 0.4" + std::string(kRough));
    const SurfaceHit h = test::flatHit();
    Pcg32 rng(9);
    int compared = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3f out = cosineHemisphere(rng.uniform(), rng.uniform());
        Vec3f in = cosineHemisphere(rng.uniform(), rng.uniform());
        in.z = -in.z;  // inside the glass
        const float fOutIn = m->evaluate(h, out, in).x / std::fabs(in.z);
        const float fInOut = m->evaluate(h, in, out).x / std::fabs(out.z);
        if (fOutIn < 1e-4f) continue;
        ++compared;
        EXPECT_NEAR(fInOut, 1.5f * 1.5f * fOutIn, 1e-3f * fInOut);
    }
    EXPECT_GT(compared, 100);
}

TEST(Bsdfs, RoughLobesApproachTheSmoothOnesAtLowRoughness) {
    test::TempDir dir;
    const std::string r = kRough;
    const auto roughGlass = test::parseMaterial(dir, "Material \"glass\" \"float uroughness\" 0.003 \"float vroughness\" 0.003" + r);
    const auto smoothGlass = test::parseMaterial(dir, "Material \"glass\"");
    const auto roughMetal = test::parseMaterial(dir, "Material \"metal\" \"float roughness\" 0.003" + r);
    const Vec3f copperEta = namedSpectrumRgb("metal-Cu-eta").value(), copperK = namedSpectrumRgb("metal-Cu-k").value();
    for (float theta : {0.0f, 45.0f, 70.0f, 150.0f, 130.0f}) {
        const Vec3f wo = test::direction(theta, 10);
        const auto rough = test::sampledAlbedo(*roughGlass, wo, 40000), smooth = test::sampledAlbedo(*smoothGlass, wo, 40000);
        EXPECT_NEAR(rough.mean.x, smooth.mean.x, 0.01f + rough.stderr3.x + smooth.stderr3.x) << "glass theta " << theta;
    }
    for (float theta : {0.0f, 45.0f, 70.0f}) {
        const Vec3f wo = test::direction(theta, 10);
        const auto rough = test::sampledAlbedo(*roughMetal, wo, 20000);
        const Vec3f exact = fresnelConductor(std::cos(theta * float(M_PI) / 180), 1.0f, copperEta, copperK);
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(rough.mean[ch], exact[ch], 0.01f) << "metal theta " << theta;
    }
}

// The reflectance of a metal at normal incidence, ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), from a
// nearly smooth metal material with the given eta and k.
TEST(Bsdfs, MetalReflectsTheConductorFresnelReflectanceAtNormalIncidence) {
    test::TempDir dir;
    const Vec3f n{0.2f, 0.9f, 1.1f}, k{3.9f, 2.4f, 2.2f};
    const auto m = test::parseMaterial(dir, "Material \"metal\" \"rgb eta\" [0.2 0.9 1.1] \"rgb k\" [3.9 2.4 2.2] "
                                            "\"float roughness\" 0.002" + std::string(kRough));
    const auto a = test::sampledAlbedo(*m, {0, 0, 1}, 20000);
    for (int ch = 0; ch < 3; ++ch) {
        const float r0 = ((n[ch] - 1) * (n[ch] - 1) + k[ch] * k[ch]) / ((n[ch] + 1) * (n[ch] + 1) + k[ch] * k[ch]);
        EXPECT_NEAR(fresnelConductor(1.0f, 1.0f, n, k)[ch], r0, 1e-5f);
        EXPECT_NEAR(a.mean[ch], r0, 0.005f) << "channel " << ch;
    }
}

// The conductor equations against the complex Fresnel amplitudes, at all angles.
TEST(Bsdfs, ConductorFresnelMatchesComplexAmplitudes) {
    const Vec3f eta{0.27f, 0.68f, 1.3f}, k{3.6f, 2.6f, 2.3f};
    for (float deg = 0; deg < 90; deg += 7.5f) {
        const double c = std::cos(deg * M_PI / 180), s2 = 1 - c * c;
        const Vec3f got = fresnelConductor(float(c), 1.0f, eta, k);
        for (int ch = 0; ch < 3; ++ch) {
            const std::complex<double> n(eta[ch], k[ch]);
            const std::complex<double> ct = std::sqrt(n * n - s2) / n;  // cos of the (complex) refraction angle
            const std::complex<double> rs = (c - n * ct) / (c + n * ct), rp = (n * c - ct) / (n * c + ct);
            const double r = 0.5 * (std::norm(rs) + std::norm(rp));
            EXPECT_NEAR(got[ch], r, 2e-5) << deg << " degrees, channel " << ch;
        }
    }
}

TEST(Bsdfs, DielectricFresnel) {
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnelDielectric(-1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);  // from inside at normal incidence
    // Brewster's angle: the parallel amplitude vanishes; the perpendicular one is ((n^2-1)/(n^2+1))^2.
    const float brewster = std::atan(1.5f), expected = 0.5f * std::pow((1.5f * 1.5f - 1) / (1.5f * 1.5f + 1), 2.0f);
    EXPECT_NEAR(fresnelDielectric(std::cos(brewster), 1.0f, 1.5f), expected, 1e-5f);
    // The same path travelled backwards reflects the same share...
    const float cosI = std::cos(0.7f), sinT = std::sin(0.7f) / 1.5f, cosT = std::sqrt(1 - sinT * sinT);
    EXPECT_NEAR(fresnelDielectric(cosI, 1.0f, 1.5f), fresnelDielectric(-cosT, 1.0f, 1.5f), 1e-6f);
    // ...and past the critical angle (41.8 degrees) inside the glass everything reflects.
    EXPECT_EQ(fresnelDielectric(-std::cos(0.75f), 1.0f, 1.5f), 1.0f);
    EXPECT_LT(fresnelDielectric(-std::cos(0.72f), 1.0f, 1.5f), 1.0f);
}

// Quadrature over the hemisphere of wh, fine near the pole where narrow lobes live.
template <class F>
double hemisphereIntegral(F&& f) {
    constexpr int nT = 1500, nP = 256;
    double sum = 0;
    for (int i = 0; i < nT; ++i) {
        const double u = (i + 0.5) / nT, theta = 0.5 * M_PI * u * u, dTheta = M_PI * u / nT;
        for (int j = 0; j < nP; ++j) {
            const double phi = 2 * M_PI * (j + 0.5) / nP;
            const Vec3f w{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))};
            sum += f(w) * std::sin(theta) * dTheta * (2 * M_PI / nP);
        }
    }
    return sum;
}

// Projected microfacet area is the macrosurface's: integral D(wh) cos(theta_h) = 1, and the
// normals visible from wo project to its cosine: integral G1(wo) max(0, wo.wh) D(wh) = cos(theta_o)
// (which holds only with the distribution's own Smith lambda).
TEST(Bsdfs, MicrofacetDistributionsAreNormalised) {
    for (MicrofacetKind kind : {MicrofacetKind::TrowbridgeReitz, MicrofacetKind::Beckmann}) {
        for (auto [ax, ay] : {std::pair{0.5f, 0.5f}, std::pair{0.15f, 0.4f}, std::pair{0.8f, 0.3f}}) {
            const MicrofacetDistribution d(kind, ax, ay);
            EXPECT_NEAR(hemisphereIntegral([&](Vec3f wh) { return d.D(wh) * wh.z; }), 1.0, 2e-3) << ax << " " << ay;
            for (float theta : {0.0f, 40.0f, 80.0f}) {
                const Vec3f wo = test::direction(theta, 35);
                const double projected = hemisphereIntegral(
                    [&](Vec3f wh) { return d.G1(wo) * std::max(0.0f, dot(wo, wh)) * d.D(wh); });
                EXPECT_NEAR(projected, wo.z, 3e-3) << "alpha " << ax << " " << ay << " theta " << theta;
            }
        }
    }
}

TEST(Bsdfs, RoughnessRemapIsPbrtV3Polynomial) {
    EXPECT_NEAR(roughnessToAlpha(0.1f), 0.4617f, 1e-3f);  // pbrt-v3 plastic's default roughness
    EXPECT_NEAR(roughnessToAlpha(0.5f), 1.1312f, 1e-3f);
    EXPECT_EQ(roughnessToAlpha(0.0f), roughnessToAlpha(1e-3f));
}

TEST(Bsdfs, OrenNayarWithSigmaZeroIsLambert) {
    const OrenNayar smooth(0);
    Pcg32 rng(5);
    for (int i = 0; i < 100; ++i) {
        const Vec3f a = cosineHemisphere(rng.uniform(), rng.uniform()), b = cosineHemisphere(rng.uniform(), rng.uniform());
        EXPECT_NEAR(smooth.f(a, b).x, 1.0f / float(M_PI), 1e-7f);
    }
    test::TempDir dir;
    const auto lambert = test::parseMaterial(dir, "Material \"matte\" \"rgb Kd\" [0.7 0.7 0.7]");
    const auto zero = test::parseMaterial(dir, "Material \"matte\" \"rgb Kd\" [0.7 0.7 0.7] \"float sigma\" 0");
    const SurfaceHit h = test::flatHit();
    EXPECT_EQ(zero->evaluate(h, test::direction(20, 0), test::direction(50, 90)).x,
              lambert->evaluate(h, test::direction(20, 0), test::direction(50, 90)).x);
}

// sigma 20 degrees: A = 0.8652, B = 0.2588; wo at 60 and wi at 30 degrees in one plane:
// f = (A + B sin 60 tan 30) / pi.
TEST(Bsdfs, OrenNayarClosedForm) {
    const OrenNayar on(20);
    EXPECT_NEAR(on.f(test::direction(60, 0), test::direction(30, 0)).x, (0.8652f + 0.2588f * 0.8660f * 0.5774f) / float(M_PI), 2e-4f);
    // Opposite azimuths: only A remains.
    EXPECT_NEAR(on.f(test::direction(60, 0), test::direction(30, 180)).x, 0.8652f / float(M_PI), 2e-4f);
    // Retro-reflection: the rough surface is brighter back toward the light than Lambert's.
    EXPECT_GT(on.f(test::direction(70, 0), test::direction(70, 0)).x, 1.0f / float(M_PI));
}

}  // namespace
}  // namespace lenslab
