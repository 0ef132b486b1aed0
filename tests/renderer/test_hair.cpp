// pbrt-v4's "hair" material (d'Eon et al. 2011, Chiang et al. 2016): a white fibre scatters all the
// light it receives, the TRT lobe's attenuation and the R lobe's tilt are d'Eon's and Chiang's
// closed forms, sampling draws directions with the density pdf() reports, the parameter forms
// give the absorption their formulas say, and curves report where a ray crossed their width.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "BsdfTesting.h"
#include "ShapeTestScenes.h"
#include "core/Pi.h"

namespace lenslab {
namespace {

// A fibre along x lying in the plane z = 0, hit at offset h across its width (v = (1 + h) / 2).
SurfaceHit fibreHit(float h) {
    SurfaceHit hit = test::flatHit();
    hit.v = 0.5f * (1 + h);
    return hit;
}

// theta: the angle from the plane normal to the fibre (0 = across it), phi around the fibre.
Vec3f aroundFibre(float thetaDeg, float phiDeg) {
    const float t = thetaDeg * kPif / 180, p = phiDeg * kPif / 180;
    return {std::sin(t), std::cos(t) * std::cos(p), std::cos(t) * std::sin(p)};
}

// The integral over the sphere of g(wi), by jittered strata uniform in wi.x (uniform on the
// sphere, by Archimedes) and in the azimuth around the fibre, where the lobes are narrow in x.
template <class G>
double sphereIntegral(G g, int n = 400) {
    Pcg32 rng(7);
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float x = -1 + 2 * (float(i) + rng.uniform()) / float(n);
            const float phi = 2 * kPif * (float(j) + rng.uniform()) / float(n);
            const float r = std::sqrt(std::max(0.0f, 1 - x * x));
            sum += g(Vec3f{x, r * std::cos(phi), r * std::sin(phi)});
        }
    return sum * 4 * M_PI / (double(n) * n);
}

std::string hairLine(const std::string& params) { return "Material \"hair\" " + params; }

TEST(Hair, WhiteFibreScattersAllLightItReceives) {
    test::TempDir dir;
    for (const char* rough : {"\"float beta_m\" 0.25 \"float beta_n\" 0.3", "\"float beta_m\" 0.5 \"float beta_n\" 0.5",
                              "\"float beta_m\" 0.8 \"float beta_n\" 0.9"}) {
        const auto m = test::parseMaterial(dir, hairLine("\"rgb sigma_a\" [0 0 0] " + std::string(rough)));
        for (float h : {-0.6f, 0.3f, 0.9f})
            for (const Vec3f wo : {aroundFibre(0, 90), aroundFibre(40, 30), aroundFibre(-70, 160)}) {
                const SurfaceHit hit = fibreHit(h);
                const double albedo = sphereIntegral([&](Vec3f wi) { return double(m->evaluate(hit, wo, wi).y); });
                EXPECT_NEAR(albedo, 1.0, 0.015) << rough << " h " << h << " wo " << wo.x << " " << wo.y << " " << wo.z;
            }
    }
}

// The TRT lobe's light against d'Eon 2011's attenuation written out: Fresnel F at the entry (of
// cos theta_o cos gamma_o), the chord's transmittance T = exp(-sigma_a 2 cos gamma_t / cos theta_t)
// once per crossing: A2 = (1 - F)^2 T^2 F. Gathered over 90 degrees of azimuth around the lobe's
// exit azimuth (4 gamma_t - 2 gamma_o + 2 pi), with the residual's quarter (A3 = A2 F T / (1 - F T),
// uniform in azimuth); R and TT lie 75 and 142 degrees away, their narrow lobes out of reach.
TEST(Hair, TheTrtLobeCarriesTwoChordsOfAbsorption) {
    test::TempDir dir;
    const float sigma = 0.3f, eta = 1.55f, h = 0.5f;
    const auto m = test::parseMaterial(
        dir, hairLine("\"rgb sigma_a\" [0.3 0.3 0.3] \"float beta_m\" 0.2 \"float beta_n\" 0.2 \"float alpha\" 0"));
    const SurfaceHit hit = fibreHit(h);
    const Vec3f wo = aroundFibre(0, 90);  // across the fibre: theta_o = 0, eta' = eta
    const double gammaO = std::asin(h), gammaT = std::asin(h / eta);
    const double cosI = std::cos(gammaO), cosT = std::sqrt(1 - std::pow(std::sin(gammaO) / eta, 2));
    const double rs = (cosI - eta * cosT) / (cosI + eta * cosT), rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    const double F = 0.5 * (rs * rs + rp * rp), T = std::exp(-sigma * 2 * std::cos(gammaT));
    const double a2 = (1 - F) * (1 - F) * T * T * F, a3 = a2 * F * T / (1 - F * T);
    const double centre = M_PI / 2 + 4 * gammaT - 2 * gammaO;
    const double gathered = sphereIntegral([&](Vec3f wi) {
        const double off = std::remainder(std::atan2(wi.z, wi.y) - centre, 2 * M_PI);
        return std::fabs(off) < M_PI / 4 ? double(m->evaluate(hit, wo, wi).y) : 0.0;
    });
    EXPECT_NEAR(gathered, a2 + a3 / 4, 0.03 * a2) << "F " << F << " T " << T;
}

// The cuticle's scales tilt the R lobe by -2 alpha (Chiang 2016, as pbrt-v4): light reflected off a
// fibre seen at elevation theta_o leaves around -(theta_o - 2 alpha), here 0 for theta_o = 2 alpha =
// 20 degrees (it would be -40 tilted the other way). The brightest elevation along R's azimuth.
TEST(Hair, TheRLobeIsTiltedByMinusTwoAlpha) {
    test::TempDir dir;
    const auto m = test::parseMaterial(
        dir, hairLine("\"rgb sigma_a\" [0.3 0.3 0.3] \"float beta_m\" 0.1 \"float beta_n\" 0.2 \"float alpha\" 10"));
    const float h = 0.5f;
    const SurfaceHit hit = fibreHit(h);
    const Vec3f wo = aroundFibre(20, 90);
    const float rAzimuth = 90 - 2 * std::asin(h) * 180 / kPif;  // -2 gamma_o from the viewer's
    float brightest = -90, peak = 0;
    for (float theta = -80; theta <= 80; theta += 0.05f) {
        const float value = m->evaluate(hit, wo, aroundFibre(theta, rAzimuth)).y;
        if (value > peak) peak = value, brightest = theta;
    }
    EXPECT_NEAR(brightest, 0, 1.0);
}

// The density sampling draws, binned in (wi.x, azimuth), against pdf() integrated over each bin;
// and the mean sample weight f cos / pdf against the integral of f cos itself.
TEST(Hair, SamplingDrawsTheDensityPdfReportsAndWeightsMatchEvaluation) {
    test::TempDir dir;
    // A clear fibre seen near its edge (h 0.95, Fresnel near 0.25) sends about 5% of what it
    // scatters into the residual of the longer paths, the share a pdf without it would miss.
    struct Setting {
        const char* params;
        std::vector<float> offsets;
    };
    for (const Setting& setting : {Setting{"\"float eumelanin\" 1.3 \"float beta_m\" 0.3", {-0.4f, 0.7f}},
                                   Setting{"\"rgb sigma_a\" [0.2 0.5 1] \"float beta_m\" 0.6 \"float beta_n\" 0.7", {-0.4f, 0.7f}},
                                   Setting{"\"rgb sigma_a\" [0 0 0]", {0.95f}}}) {
        const char* params = setting.params;
        const auto m = test::parseMaterial(dir, hairLine(params));
        for (float h : setting.offsets)
            for (const Vec3f wo : {aroundFibre(10, 80), aroundFibre(-50, 200)}) {
                const SurfaceHit hit = fibreHit(h);
                constexpr int kBinsX = 10, kBinsPhi = 8, kSamples = 200000;
                const auto binOf = [&](Vec3f w) {
                    const int bx = std::clamp(int((w.x + 1) / 2 * kBinsX), 0, kBinsX - 1);
                    const float phi = std::atan2(w.z, w.y) + kPif;
                    return bx * kBinsPhi + std::clamp(int(phi / (2 * kPif) * kBinsPhi), 0, kBinsPhi - 1);
                };
                std::vector<double> expected(kBinsX * kBinsPhi, 0), drawn(kBinsX * kBinsPhi, 0);
                constexpr int kStrata = 400;
                const double pdfTotal = sphereIntegral(
                    [&](Vec3f wi) {
                        const double p = m->pdf(hit, wo, wi);
                        expected[binOf(wi)] += p * 4 * M_PI / (double(kStrata) * kStrata);
                        return p;
                    },
                    kStrata);
                EXPECT_NEAR(pdfTotal, 1.0, 0.01);

                Pcg32 rng(11);
                double weightSum = 0, weightSum2 = 0;
                for (int i = 0; i < kSamples; ++i) {
                    BsdfSample s;
                    const float a = rng.uniform(), b = rng.uniform(), c = rng.uniform();
                    if (!m->sample(hit, wo, a, b, c, s)) continue;
                    drawn[binOf(s.wi)] += 1.0 / kSamples;
                    weightSum += s.weight.y;
                    weightSum2 += double(s.weight.y) * s.weight.y;
                }
                for (std::size_t k = 0; k < expected.size(); ++k) {
                    const double sigma = std::sqrt(expected[k] * (1 - expected[k]) / kSamples);
                    EXPECT_NEAR(drawn[k], expected[k], 5 * sigma + 0.02 * expected[k] + 1e-4) << params << " bin " << k;
                }
                const double mean = weightSum / kSamples;
                const double se = std::sqrt(std::max(0.0, weightSum2 / kSamples - mean * mean) / kSamples);
                const double integral = sphereIntegral([&](Vec3f wi) { return double(m->evaluate(hit, wo, wi).y); });
                EXPECT_NEAR(mean, integral, 0.02 * integral + 3 * se) << params << " h " << h;
            }
    }
}

// f(wo, wi) for a fixed pair of directions, green channel unless told.
Vec3f valueOf(const test::TempDir& dir, const std::string& params) {
    const auto m = test::parseMaterial(dir, hairLine(params));
    return m->evaluate(fibreHit(0.2f), aroundFibre(20, 70), aroundFibre(-15, 250));
}

void expectSameColour(Vec3f a, Vec3f b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f + 1e-4f * b.x);
    EXPECT_NEAR(a.y, b.y, 1e-5f + 1e-4f * b.y);
    EXPECT_NEAR(a.z, b.z, 1e-5f + 1e-4f * b.z);
}

TEST(Hair, ParameterFormsGiveTheirAbsorption) {
    test::TempDir dir;
    // Melanin: eumelanin (0.419, 0.697, 1.37) and pheomelanin (0.187, 0.4, 1.05) per unit (d'Eon 2011).
    expectSameColour(valueOf(dir, "\"float eumelanin\" 2 \"float pheomelanin\" 0.5"),
                     valueOf(dir, "\"rgb sigma_a\" [0.9315 1.594 3.265]"));
    // pbrt-v4's default is brown hair, eumelanin 1.3.
    expectSameColour(valueOf(dir, ""), valueOf(dir, "\"float eumelanin\" 1.3"));
    // Chiang 2016's inversion at beta_n 0.3: sigma_a = (ln 0.5 / 5.88862)^2 = 0.0138556.
    expectSameColour(valueOf(dir, "\"rgb reflectance\" [0.5 0.5 0.5]"), valueOf(dir, "\"rgb sigma_a\" [0.0138556 0.0138556 0.0138556]"));
    expectSameColour(valueOf(dir, "\"rgb color\" [0.5 0.5 0.5]"), valueOf(dir, "\"rgb reflectance\" [0.5 0.5 0.5]"));
    // sigma_a wins over the others, as in pbrt-v4; absorption darkens.
    expectSameColour(valueOf(dir, "\"rgb sigma_a\" [1 1 1] \"float eumelanin\" 5"), valueOf(dir, "\"rgb sigma_a\" [1 1 1]"));
    EXPECT_LT(valueOf(dir, "\"float eumelanin\" 3").y, 0.5f * valueOf(dir, "\"float eumelanin\" 0.3").y);
}

TEST(Hair, BadParametersAreRefusedNamingTheLine) {
    test::TempDir dir;
    const std::string header = "Camera \"perspective\"\nWorldBegin\n";
    for (const char* bad : {"\"float beta_m\" 0", "\"float beta_n\" 1.5", "\"float eta\" -1", "\"float alpha\" 120",
                            "\"rgb sigma_a\" [0.1 -1 0.1]", "\"rgb reflectance\" [0 0.5 0.5]", "\"float eumelanin\" -2"}) {
        const std::string msg = test::sceneErrorOf(dir.write("s.pbrt", header + "\nMaterial \"hair\" " + bad + "\n"));
        EXPECT_NE(msg.find("s.pbrt:4"), std::string::npos) << bad << ": " << msg;
        EXPECT_NE(msg.find("hair"), std::string::npos) << bad << ": " << msg;
    }
}

// h = 2v - 1 is the hit's offset off the curve's axis, over its radius, measured across the ray
// (along -d x T) for every curve type.
TEST(Hair, CurvesReportTheOffsetAcrossTheirWidth) {
    for (const char* type : {"flat", "cylinder"}) {
        test::TempDir dir;
        const auto g = test::geometryOf(dir, std::string("Shape \"curve\" \"point P\" [-2 0 5  -1 0 5  1 0 5  2 0 5] "
                                                         "\"float width\" 0.5 \"string type\" \"") + type + "\"");
        for (float y0 : {-0.2f, -0.1f, 0.0f, 0.15f, 0.23f}) {
            Intersection it;
            const Vec3f d = normalize(Vec3f{0.1f, 0, 1});
            ASSERT_TRUE(test::trace(*g, {0.3f, y0, 0}, d, it)) << type << " " << y0;
            const Vec3f t = normalize(it.hit.dpdu);
            const Vec3f across = normalize(cross(-d, t));
            const float expected = dot(it.hit.p - Vec3f{it.hit.p.x, 0, 5}, across) / 0.25f;
            EXPECT_NEAR(2 * it.hit.v - 1, expected, 0.02f) << type << " " << y0;
            EXPECT_NEAR(std::fabs(2 * it.hit.v - 1), std::fabs(y0) / 0.25f, 0.05f) << type << " " << y0;
        }
    }
}

}  // namespace
}  // namespace lenslab
