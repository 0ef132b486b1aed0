// Materials as scenes give them: pbrt-v3's parameters and defaults, named metal spectra, mixes,
// pass-through surfaces, measured BRDF files, and clear errors for what cannot be built.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>

#include "BsdfTesting.h"
#include "core/Pi.h"
#include "materials/Fresnel.h"
#include "materials/MetalSpectra.h"
#include "core/Spectrum.h"

namespace lenslab {
namespace {

std::string materialErrorOf(const test::TempDir& dir, const std::string& directive) {
    try {
        test::parseMaterial(dir, directive);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Materials, MetalDefaultsToPbrtV3Copper) {
    test::TempDir dir;
    const auto byDefault = test::parseMaterial(dir, "Material \"metal\"");
    const auto named = test::parseMaterial(dir, "Material \"metal\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" \"metal-Cu-k\" "
                                                "\"float roughness\" 0.01");
    const SurfaceHit h = test::flatHit();
    const Vec3f wo = test::direction(30, 0), wi = test::direction(31, 180);
    for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(byDefault->evaluate(h, wo, wi)[ch], named->evaluate(h, wo, wi)[ch]);
    EXPECT_GT(byDefault->evaluate(h, wo, wi).x, 1.0f);  // a narrow highlight
}

// The tables converted to RGB: copper's eta and k, and each metal's reflectance at normal
// incidence against the same reflectance computed wavelength by wavelength and converted after
// (for a white whose RGB is 1). The RGB route is what pbrt-v3's default (RGB) build does; it
// stays within 0.04 of the spectral one.
TEST(Materials, NamedMetalSpectraGiveTheMeasuredColours) {
    const Vec3f cuEta = namedSpectrumRgb("metal-Cu-eta").value(), cuK = namedSpectrumRgb("metal-Cu-k").value();
    EXPECT_NEAR(cuEta.x, 0.204f, 2e-3f);
    EXPECT_NEAR(cuEta.y, 0.922f, 2e-3f);
    EXPECT_NEAR(cuEta.z, 1.102f, 2e-3f);
    EXPECT_NEAR(cuK.x, 3.884f, 2e-3f);
    EXPECT_NEAR(cuK.y, 2.463f, 2e-3f);
    EXPECT_NEAR(cuK.z, 2.140f, 2e-3f);
    const struct {
        const char* metal;
        Vec3f spectralF0;
    } metals[] = {{"Cu", {0.933f, 0.640f, 0.534f}}, {"Au", {0.994f, 0.789f, 0.337f}},
                  {"Ag", {0.970f, 0.960f, 0.913f}}, {"Al", {0.914f, 0.921f, 0.925f}}};
    for (const auto& m : metals) {
        const Vec3f eta = namedSpectrumRgb(std::string("metal-") + m.metal + "-eta").value();
        const Vec3f k = namedSpectrumRgb(std::string("metal-") + m.metal + "-k").value();
        const Vec3f f0 = fresnelConductor(1.0f, 1.0f, eta, k);
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(f0[ch], m.spectralF0[ch], 0.04f) << m.metal << " channel " << ch;
    }
    for (const char* n : {"metal-CuZn-eta", "metal-CuZn-k", "metal-MgO-eta", "metal-MgO-k", "metal-TiO2-eta", "metal-TiO2-k"})
        EXPECT_TRUE(namedSpectrumRgb(n).has_value()) << n;
    EXPECT_FALSE(namedSpectrumRgb("metal-Pb-eta").has_value());
    EXPECT_NEAR(namedSpectrumRgb("metal-TiO2-k")->y, 0.0f, 1e-3f);  // a dielectric: no absorption
}

// pbrt-v3's mix scales the first named material by "amount", per channel.
TEST(Materials, MixWeightsTheFirstMaterialByAmount) {
    test::TempDir dir;
    const auto mix = test::parseMaterial(dir, "MakeNamedMaterial \"white\" \"string type\" \"matte\" \"rgb Kd\" [1 1 1]\n"
                                              "MakeNamedMaterial \"black\" \"string type\" \"matte\" \"rgb Kd\" [0 0 0]\n"
                                              "Material \"mix\" \"string namedmaterial1\" \"white\" "
                                              "\"string namedmaterial2\" \"black\" \"rgb amount\" [0.2 0.5 0.9]");
    const SurfaceHit h = test::flatHit();
    const Vec3f f = mix->evaluate(h, test::direction(10, 0), test::direction(0, 0)) * kPif;
    EXPECT_NEAR(f.x, 0.2f, 1e-6f);
    EXPECT_NEAR(f.y, 0.5f, 1e-6f);
    EXPECT_NEAR(f.z, 0.9f, 1e-6f);
    const auto a = test::sampledAlbedo(*mix, test::direction(40, 0), 1000);
    EXPECT_NEAR(a.mean.y, 0.5f, 1e-5f);  // every sample carries f cos / pdf exactly
}

TEST(Materials, NoneAndInterfaceLetRaysPassStraightThrough) {
    test::TempDir dir;
    for (const char* d : {"Material \"none\"", "Material \"interface\"", "Material \"\""}) {
        const auto m = test::parseMaterial(dir, d);
        EXPECT_TRUE(m->isSpecular());
        const SurfaceHit h = test::flatHit();
        const Vec3f wo = normalize(Vec3f{0.3f, -0.2f, 0.9f});
        BsdfSample s;
        ASSERT_TRUE(m->sample(h, wo, 0.7f, 0.1f, 0.9f, s)) << d;
        EXPECT_TRUE(s.specular);
        EXPECT_NEAR(dot(s.wi, -wo), 1.0f, 1e-6f);
        EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
        EXPECT_EQ(m->evaluate(h, wo, -wo).x, 0.0f);
    }
}

// A sphere without a surface in front of the camera: the image is the light behind it.
TEST(Materials, NoneSphereIsInvisibleInARender) {
    test::TempDir dir;
    const auto scene = [&](const std::string& world) {
        return dir.write("none.pbrt", "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 20\n"
                                      "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
                                      "LightSource \"infinite\" \"rgb L\" [0.25 0.5 0.75]\n" + world + "\nWorldEnd\n");
    };
    const Image im = test::render(scene("Material \"none\"\nShape \"sphere\""), 8, 8, 1).image;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_NEAR(test::lum(im, x, y), 0.5f, 1e-4f) << x << "," << y;
}

// A convex object under a uniform sky of radiance 1 reflects, by direct lighting alone, its
// directional albedo. The path tracer gets there by combining light samples and BSDF samples with
// multiple importance sampling, which is unbiased only when each material's pdf() is the density
// its sample() draws from.
TEST(Materials, UnderAUniformSkyARenderShowsTheAlbedo) {
    test::TempDir dir;
    const std::string r = " \"bool remaproughness\" \"false\"";
    const std::string materials[] = {
        "Material \"plastic\" \"rgb Kd\" [0.5 0.3 0.1] \"rgb Ks\" [0.5 0.5 0.5] \"float roughness\" 0.2" + r,
        "Material \"metal\" \"float roughness\" 0.3" + r,
        "Material \"substrate\" \"rgb Kd\" [0.6 0.6 0.6] \"rgb Ks\" [0.2 0.2 0.2]",
        "Material \"uber\" \"rgb Kd\" [0.3 0.3 0.3] \"rgb Ks\" [0.3 0.3 0.3] \"rgb Kr\" [0.3 0.3 0.3]",
        "Material \"matte\" \"rgb Kd\" [0.8 0.8 0.8] \"float sigma\" 40"};
    for (const std::string& m : materials) {
        // The centre of the sphere seen head-on: the outgoing direction is the normal.
        const std::string scene = dir.write("sky.pbrt",
            "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 1\n"
            "Film \"image\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
            "Integrator \"path\" \"integer maxdepth\" 1\nWorldBegin\n"
            "LightSource \"infinite\" \"rgb L\" [1 1 1]\n" + m + "\nShape \"sphere\"\nWorldEnd\n");
        const Image im = test::render(scene, 4, 4, 1024).image;
        double mean = 0;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) mean += test::lum(im, x, y) / 16.0;
        const auto a = test::sampledAlbedo(*test::parseMaterial(dir, m), {0, 0, 1}, 200000);
        const float albedo = (a.mean.x + a.mean.y + a.mean.z) / 3;
        EXPECT_NEAR(mean, albedo, 0.015 * albedo) << m;
    }
}

// Uber with opacity 0.25: three quarters of the light passes straight through, unbent.
TEST(Materials, UberOpacityPassesTheRestStraightThrough) {
    test::TempDir dir;
    const auto m = test::parseMaterial(dir, "Material \"uber\" \"rgb opacity\" [0.25 0.25 0.25] \"rgb Kd\" [0 0 0] "
                                            "\"rgb Ks\" [0 0 0]");
    const SurfaceHit h = test::flatHit();
    const Vec3f wo = test::direction(35, 60);
    Pcg32 rng(3);
    double through = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        const float a = rng.uniform(), b = rng.uniform(), c = rng.uniform();
        if (m->sample(h, wo, a, b, c, s) && dot(s.wi, -wo) > 0.99999f) through += s.weight.x;
    }
    EXPECT_NEAR(through / n, 0.75, 1e-3);
}

TEST(Materials, GlassIsSpecularOnlyWhenSmooth) {
    test::TempDir dir;
    EXPECT_TRUE(test::parseMaterial(dir, "Material \"glass\"")->isSpecular());
    EXPECT_TRUE(test::parseMaterial(dir, "Material \"glass\" \"float index\" 1.33")->isSpecular());
    EXPECT_FALSE(test::parseMaterial(dir, "Material \"glass\" \"float uroughness\" 0.1")->isSpecular());
    EXPECT_FALSE(test::parseMaterial(dir, "Material \"metal\"")->isSpecular());
    // "index" is pbrt-v3's older name for eta: water's reflectance at normal incidence.
    const auto water = test::parseMaterial(dir, "Material \"glass\" \"float index\" 1.33");
    const auto a = test::sampledAlbedo(*water, {0, 0, 1}, 20000, 1, 1.33f);
    EXPECT_NEAR(a.mean.x, 1.0f, 1e-5f);  // reflected plus transmitted energy, Kr = Kt = 1
}

// A float texture drives roughness like the number it holds.
TEST(Materials, RoughnessMayBeAFloatTexture) {
    test::TempDir dir;
    const auto textured = test::parseMaterial(dir, "Texture \"r\" \"float\" \"constant\" \"float value\" 0.3\n"
                                                   "Material \"metal\" \"texture roughness\" \"r\"");
    const auto number = test::parseMaterial(dir, "Material \"metal\" \"float roughness\" 0.3");
    const SurfaceHit h = test::flatHit();
    const Vec3f wo = test::direction(40, 0), wi = test::direction(30, 170);
    EXPECT_EQ(textured->evaluate(h, wo, wi).y, number->evaluate(h, wo, wi).y);
}

// --- measured BRDFs ------------------------------------------------------------------------------

struct Record {
    float thetaI, phiI, thetaO, phiO;
    std::vector<double> values;  // at 400, 550, 700 nm
};

const std::vector<Record> kRecords = {{0.2f, 0.0f, 0.3f, kPif, {0.10, 0.20, 0.30}},
                                      {0.8f, 0.0f, 0.8f, 0.0f, {0.90, 0.50, 0.10}},
                                      {1.2f, 0.0f, 0.5f, 0.5f * kPif, {0.05, 0.05, 0.40}},
                                      {1.0f, 0.0f, 1.3f, 0.0f, {0.30, 0.30, 0.30}}};

std::string cornellFile() {
    std::string text = "# Cornell-style irregular isotropic BRDF written by the test\n# num wls\n3\n# wls\n400 550 700\n";
    for (const Record& r : kRecords) {
        text += std::to_string(r.thetaI) + " " + std::to_string(r.phiI) + " " + std::to_string(r.thetaO) + " " +
                std::to_string(r.phiO);
        for (double v : r.values) text += " " + std::to_string(v);
        text += "\n";
    }
    return text;
}

TEST(Materials, MeasuredBrdfFileReturnsItsSamples) {
    test::TempDir dir;
    dir.write("paint.brdf", cornellFile());
    const auto m = test::parseMaterial(dir, "Material \"measured\" \"string filename\" \"paint.brdf\"");
    const SurfaceHit h = test::flatHit();
    const auto deg = [](float rad) { return rad * 180 / kPif; };
    for (const Record& r : kRecords) {
        const Vec3f expected = sampledSpectrumToRgb({400, 550, 700}, r.values);
        const Vec3f wi = test::direction(deg(r.thetaI), deg(r.phiI)), wo = test::direction(deg(r.thetaO), deg(r.phiO));
        const Vec3f f = m->evaluate(h, wo, wi) / wi.z;
        const Vec3f swapped = m->evaluate(h, wi, wo) / wo.z;
        // Isotropic: turning both directions about the normal changes nothing.
        const Vec3f turned = m->evaluate(h, test::direction(deg(r.thetaO), deg(r.phiO) + 70),
                                         test::direction(deg(r.thetaI), deg(r.phiI) + 70)) / wi.z;
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(f[ch], expected[ch], 1e-3f * std::max(1.0f, expected[ch])) << "record " << r.thetaI;
            EXPECT_NEAR(swapped[ch], f[ch], 1e-5f);
            EXPECT_NEAR(turned[ch], f[ch], 1e-4f);
        }
    }
}

TEST(Materials, MeasuredBrdfFileErrorsNameTheProblem) {
    test::TempDir dir;
    dir.write("short.brdf", "3\n400 550 700\n0.1 0 0.2 0 0.5 0.5\n");
    EXPECT_NE(materialErrorOf(dir, "Material \"measured\" \"string filename\" \"short.brdf\"").find("not a whole number of records"),
              std::string::npos);
    dir.write("words.brdf", "1\n500\n0.1 0 0.2 zero 0.5\n");
    EXPECT_NE(materialErrorOf(dir, "Material \"measured\" \"string filename\" \"words.brdf\"").find("line 3: 'zero'"),
              std::string::npos);
    dir.write("tiny.merl", "not a table");
    EXPECT_NE(materialErrorOf(dir, "Material \"measured\" \"string filename\" \"tiny.merl\"").find("MERL"), std::string::npos);
    EXPECT_NE(materialErrorOf(dir, "Material \"measured\"").find("needs \"string filename\""), std::string::npos);
    EXPECT_NE(materialErrorOf(dir, "Material \"measured\" \"string filename\" \"absent.brdf\"").find("cannot open"), std::string::npos);
}

// A MERL table whose entries encode their own indices (red: theta_half bin + 1, green:
// theta_diff bin + 1, blue: phi_diff bin + 1, after MERL's channel scales) is looked up at the
// bins of the half and difference angles of each direction pair.
TEST(Materials, MerlTableIsIndexedByHalfAndDifferenceAngles) {
    test::TempDir dir;
    constexpr int nH = 90, nD = 90, nP = 180;
    const std::size_t n = std::size_t(nH) * nD * nP;
    std::vector<double> table(3 * n);
    for (int h = 0; h < nH; ++h)
        for (int d = 0; d < nD; ++d)
            for (int p = 0; p < nP; ++p) {
                const std::size_t i = (std::size_t(h) * nD + d) * nP + p;
                table[i] = 1500.0 * (h + 1);
                table[n + i] = 1500.0 / 1.15 * (d + 1);
                table[2 * n + i] = 1500.0 / 1.66 * (p + 1);
            }
    table[((std::size_t(3) * nD + 4) * nP + 5)] = -1;  // unmeasured: reads as zero
    {
        std::ofstream out(dir.path() + "/index.binary", std::ios::binary);
        const std::int32_t dims[3] = {nH, nD, nP};
        out.write(reinterpret_cast<const char*>(dims), sizeof dims);
        out.write(reinterpret_cast<const char*>(table.data()), std::streamsize(table.size() * sizeof(double)));
    }
    const auto m = test::parseMaterial(dir, "Material \"measured\" \"string filename\" \"index.binary\"");
    const SurfaceHit hit = test::flatHit();
    // The direction pair at the centre of bin (h, d, p), the half vector in the x-z plane.
    const auto pairAt = [](int h, int d, int p, Vec3f& wo, Vec3f& wi) {
        const float thetaH = (h + 0.5f) / nH, tH = thetaH * thetaH * 0.5f * kPif;
        const float tD = (d + 0.5f) / nD * 0.5f * kPif, pD = (p + 0.5f) / nP * kPif;
        const Vec3f wd{std::sin(tD) * std::cos(pD), std::sin(tD) * std::sin(pD), std::cos(tD)};
        wi = {wd.x * std::cos(tH) + wd.z * std::sin(tH), wd.y, -wd.x * std::sin(tH) + wd.z * std::cos(tH)};
        const Vec3f wh{std::sin(tH), 0, std::cos(tH)};
        wo = 2.0f * dot(wi, wh) * wh - wi;
    };
    const int bins[][3] = {{0, 0, 0}, {20, 30, 100}, {45, 10, 179}, {60, 20, 7}, {3, 4, 5}};
    for (const auto& b : bins) {
        Vec3f wo, wi;
        pairAt(b[0], b[1], b[2], wo, wi);
        ASSERT_GT(wo.z, 0);
        ASSERT_GT(wi.z, 0);
        const Vec3f f = m->evaluate(hit, wo, wi) / wi.z;
        if (b[0] == 3) {
            EXPECT_EQ(f.x, 0.0f);
            continue;
        }
        EXPECT_NEAR(f.x, b[0] + 1, 1e-3f);
        EXPECT_NEAR(f.y, b[1] + 1, 1e-3f);
        EXPECT_NEAR(f.z, b[2] + 1, 1e-3f);
    }
}

TEST(Materials, DefinitionErrorsNameTheProblem) {
    test::TempDir dir;
    EXPECT_NE(materialErrorOf(dir, "Material \"mix\" \"string namedmaterial1\" \"a\" \"string namedmaterial2\" \"b\"")
                  .find("undefined material \"a\""),
              std::string::npos);
    EXPECT_NE(materialErrorOf(dir, "MakeNamedMaterial \"a\" \"rgb Kd\" [1 1 1]").find("needs \"string type\""), std::string::npos);
    EXPECT_NE(materialErrorOf(dir, "Material \"metal\" \"string distribution\" \"phong\"").find("beckmann"), std::string::npos);
    EXPECT_NE(materialErrorOf(dir, "Material \"glass\" \"float eta\" 0").find("must be positive"), std::string::npos);
    EXPECT_NE(materialErrorOf(dir, "Material \"fourier\"").find("material \"fourier\" is not supported"), std::string::npos);
    const std::string uber = "MakeNamedMaterial \"u\" \"string type\" \"uber\"\n";
    std::string nested = uber + "MakeNamedMaterial \"m1\" \"string type\" \"mix\" \"string namedmaterial1\" \"u\" "
                                "\"string namedmaterial2\" \"u\"\n";
    nested += "Material \"mix\" \"string namedmaterial1\" \"m1\" \"string namedmaterial2\" \"m1\"";
    EXPECT_NE(materialErrorOf(dir, nested).find("lobes"), std::string::npos);
}

}  // namespace
}  // namespace lenslab
