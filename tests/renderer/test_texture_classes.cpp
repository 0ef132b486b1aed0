// pbrt-v3's texture classes evaluated at known points: combinations exact, mappings per pbrt's
// formulas, checkerboards by parity, noise as pbrt-v3's own code computes it.
#include <cmath>

#include "sampling/Noise.h"
#include "TextureTests.h"

namespace lenslab {
namespace {

using namespace test;

TEST(TextureClasses, ScaleMixAndBilerpAreExact) {
    TextureMap named;
    named.spectra["a"] = makeConstantTexture({0.5f, 0.25f, 2});
    named.floats["half"] = makeConstantTexture({0.25f, 0.25f, 0.25f});
    const SurfaceHit h = hitAt(0.25f, 0.75f);
    expectRgb(texture("scale", {textureRef("tex1", "a"), rgbParam("tex2", {2, 4, 0.5f})}, TextureKind::Spectrum, {}, named)
                  ->evaluate(h),
              {1, 1, 1});
    expectRgb(texture("scale", {floatParam("tex1", 3)}, TextureKind::Float)->evaluate(h), {3, 3, 3});  // tex2 = 1
    // (1 - amount) tex1 + amount tex2; the amount is a float texture.
    expectRgb(texture("mix", {textureRef("tex1", "a"), rgbParam("tex2", {1, 1, 0}), textureRef("amount", "half")},
                      TextureKind::Spectrum, {}, named)
                  ->evaluate(h),
              {0.625f, 0.4375f, 1.5f});
    expectRgb(texture("mix", {}, TextureKind::Float)->evaluate(h), {0.5f, 0.5f, 0.5f});  // 0 and 1, amount 0.5
    // Bilinear: (1-s)(1-t) v00 + (1-s) t v01 + s (1-t) v10 + s t v11 at (s, t) = (0.25, 0.75).
    const float bilinear = 0.1875f * 1 + 0.5625f * 2 + 0.0625f * 3 + 0.1875f * 4;
    expectRgb(texture("bilerp", {floatParam("v00", 1), floatParam("v01", 2), floatParam("v10", 3), floatParam("v11", 4)},
                      TextureKind::Float)
                  ->evaluate(h),
              {bilinear, bilinear, bilinear});
    const Vec3f corner = texture("bilerp", {})->evaluate(hitAt(0, 1));  // v01 defaults to 1
    expectRgb(corner, {1, 1, 1});
}

TEST(TextureClasses, FloatAndSpectrumTexturesAreSeparateNames) {
    TextureMap named;
    named.floats["x"] = makeConstantTexture({0.5f, 0.5f, 0.5f});
    try {
        texture("scale", {textureRef("tex1", "x")}, TextureKind::Spectrum, {}, named);
        FAIL() << "a spectrum parameter found a float texture";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("undeclared spectrum texture \"x\" (\"x\" is a texture of the other kind)"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(texture("uv", {}, TextureKind::Float), SceneError);  // spectrum only, as in pbrt-v3
    EXPECT_THROW(texture("ptex", {}), SceneError);
}

// The uv texture shows the mapped (s, t) as red and green (fractional parts), so it reads out
// each mapping.
TEST(TextureMappings, MapKnownPointsAsPbrtV3) {
    // uv: s = uscale u + udelta, t = vscale v + vdelta.
    expectRgb(texture("uv", {floatParam("uscale", 2), floatParam("vscale", 3), floatParam("udelta", 0.1),
                             floatParam("vdelta", 0.2)})
                  ->evaluate(hitAt(0.2f, 0.1f)),
              {0.5f, 0.5f, 0}, 1e-6f);
    // spherical, around the texture space's origin (1, 2, 3): s = theta / pi, t = phi / 2pi.
    const Transform at123 = translate(1, 2, 3);
    auto spherical = texture("uv", {stringParam("mapping", "spherical")}, TextureKind::Spectrum, at123);
    expectRgb(spherical->evaluate(hitAt(0, 0, {1, 3, 3})), {0.5f, 0.25f, 0}, 1e-6f);          // +y: theta 90, phi 90
    expectRgb(spherical->evaluate(hitAt(0, 0, {1 - 1, 2 - 1, 3})), {0.5f, 0.625f, 0}, 1e-6f);  // phi 225 degrees
    expectRgb(spherical->evaluate(hitAt(0, 0, {1 + 1, 2, 3 + 1})), {0.25f, 0, 0}, 1e-6f);      // theta 45, phi 0
    // cylindrical: s = (pi + atan2(y, x)) / 2pi, t = z of the unit direction.
    auto cylindrical = texture("uv", {stringParam("mapping", "cylindrical")}, TextureKind::Spectrum, at123);
    expectRgb(cylindrical->evaluate(hitAt(0, 0, {1, 3, 4})), {0.75f, std::sqrt(0.5f), 0}, 1e-6f);
    // planar: s = udelta + p.v1, t = vdelta + p.v2 with the world-space point.
    expectRgb(texture("uv", {stringParam("mapping", "planar"), vectorParam("v1", {1, 0, 0}), vectorParam("v2", {0, 0, 1}),
                             floatParam("udelta", 0.25), floatParam("vdelta", 0.5)},
                      TextureKind::Spectrum, at123)
                  ->evaluate(hitAt(0, 0, {0.5f, 9, 0.125f})),
              {0.75f, 0.625f, 0}, 1e-6f);
    EXPECT_THROW(texture("uv", {stringParam("mapping", "cubic")}), SceneError);
}

TEST(TextureClasses, CheckerboardsTakeTex1WhereTheCellIndicesSumEven) {
    const Vec3f white{1, 1, 1}, black{0, 0, 0};
    auto board = texture("checkerboard", {floatParam("uscale", 4), floatParam("vscale", 4)});
    expectRgb(board->evaluate(hitAt(0.1f, 0.1f)), white);   // cell (0, 0)
    expectRgb(board->evaluate(hitAt(0.3f, 0.1f)), black);   // cell (1, 0)
    expectRgb(board->evaluate(hitAt(0.3f, 0.3f)), white);   // cell (1, 1)
    expectRgb(board->evaluate(hitAt(-0.1f, 0.1f)), black);  // cell (-1, 0): odd
    expectRgb(board->evaluate(hitAt(-0.1f, -0.1f)), white);
    // 3D: cells of the texture space, the hit point under the directive's transform as pbrt-v3
    // maps it (not its inverse): shifted by half a cell in x, then doubled.
    auto solid = texture("checkerboard", {intParam("dimension", 3), rgbParam("tex1", {1, 0, 0}), rgbParam("tex2", {0, 0, 1})},
                         TextureKind::Spectrum, scale(2, 2, 2) * translate(0.5, 0, 0));
    expectRgb(solid->evaluate(hitAt(0, 0, {0.2f, 0.2f, 0.2f})), {0, 0, 1});   // texture point (1.4, .4, .4)
    expectRgb(solid->evaluate(hitAt(0, 0, {0.7f, 0.2f, 0.2f})), {1, 0, 0});   // (2.4, .4, .4)
    expectRgb(solid->evaluate(hitAt(0, 0, {-0.2f, 0.2f, 0.2f})), {1, 0, 0});  // (0.6, .4, .4)
    expectRgb(solid->evaluate(hitAt(0, 0, {0.2f, -0.2f, 0.2f})), {1, 0, 0});  // (1.4, -.4, .4)
    EXPECT_THROW(texture("checkerboard", {intParam("dimension", 4)}), SceneError);
}

// Reference values from pbrt-v3's Noise, FBm and Turbulence (src/core/texture.cpp) compiled on
// their own, with a zero footprint (all octaves).
TEST(Noise, MatchesPbrtV3) {
    EXPECT_NEAR(perlinNoise({0.3f, 0.7f, 0.1f}), -0.0971813723f, 1e-6f);
    EXPECT_NEAR(perlinNoise({-4.25f, 17.6f, 3.3f}), -0.292898297f, 1e-6f);
    EXPECT_NEAR(perlinNoise({100.5f, -33.3f, 0.77f}), -0.310668409f, 1e-6f);
    EXPECT_EQ(perlinNoise({3, -7, 12}), 0.0f);  // zero at lattice points
    EXPECT_EQ(perlinNoise({1e30f, 0.5f, 0.5f}), 0.0f);
    EXPECT_EQ(perlinNoise({std::nanf(""), 0.5f, 0.5f}), 0.0f);
    EXPECT_NEAR(fractionalBrownianMotion({0.3f, 1.7f, -2.1f}, 0.5f, 8), -0.59823966f, 1e-5f);
    EXPECT_NEAR(turbulence({0.3f, 1.7f, -2.1f}, 0.5f, 8), 0.701446116f, 1e-5f);
    auto fbm = texture("fbm", {}, TextureKind::Float);
    expectRgb(fbm->evaluate(hitAt(0, 0, {0.3f, 1.7f, -2.1f})), {-0.59823966f, -0.59823966f, -0.59823966f}, 1e-5f);
}

// The gradient (pbrt-v4's DNoise: forward differences over 0.01) takes the three nearby values
// from the point's own lattice cell where they share it: each must be perlinNoise's own, bit for
// bit, there and where a step crosses into the next cell (x, y or z just below an integer).
TEST(Noise, GradientIsTheForwardDifferencesOfTheNoise) {
    int crossings = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3f p{0.0137f * float(i) - 9.1f, 0.0291f * float(i % 97) + 0.995f, 3.996f - 0.0043f * float(i % 13)};
        const float n = perlinNoise(p);
        const Vec3f expected = Vec3f{perlinNoise(p + Vec3f{0.01f, 0, 0}) - n, perlinNoise(p + Vec3f{0, 0.01f, 0}) - n,
                                     perlinNoise(p + Vec3f{0, 0, 0.01f}) - n} / 0.01f;
        const Vec3f g = perlinNoiseGradient(p);
        EXPECT_EQ(g.x, expected.x) << i;
        EXPECT_EQ(g.y, expected.y) << i;
        EXPECT_EQ(g.z, expected.z) << i;
        crossings += std::floor(p.x + 0.01f) != std::floor(p.x) || std::floor(p.y + 0.01f) != std::floor(p.y) ||
                     std::floor(p.z + 0.01f) != std::floor(p.z);
    }
    EXPECT_GT(crossings, 100);
}

// Over many points: fbm averages to about zero, turbulence (wrinkled) is positive, marble stays
// within its spline's colours (times pbrt's 1.5), windy is bounded; and they repeat exactly.
TEST(Noise, TexturesHaveTheirRangesAndAreDeterministic) {
    auto fbm = texture("fbm", {}, TextureKind::Float);
    auto wrinkled = texture("wrinkled", {}, TextureKind::Float);
    auto windy = texture("windy", {}, TextureKind::Float);
    auto marble = texture("marble", {floatParam("scale", 3), floatParam("variation", 1)});
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const SurfaceHit h = hitAt(0, 0, {0.37f * i + 0.11f, 0.29f * j - 3.3f, 0.13f * (i - j)});
            const float f = fbm->evaluate(h).x;
            sum += f;
            sumSq += f * f;
            ++n;
            EXPECT_LT(std::fabs(f), 2.0f);
            EXPECT_GT(wrinkled->evaluate(h).x, 0.0f);
            EXPECT_LT(std::fabs(windy->evaluate(h).x), 2.0f);
            const Vec3f m = marble->evaluate(h);
            for (float c : {m.x, m.y, m.z}) {
                EXPECT_GE(c, 1.5f * 0.2f - 1e-5f);
                EXPECT_LE(c, 1.5f * 0.6f + 1e-5f);
            }
            expectRgb(marble->evaluate(h), m, 0);
        }
    EXPECT_LT(std::fabs(sum / n), 0.05);
    EXPECT_GT(sumSq / n, 0.01);  // not flat
}

// pbrt-v3 gives "inside" (default 1) to the area between dots and "outside" (default 0) to the
// dots. Cell (0, 1) has a dot centred at (0.025598, 0.934238); cell (0, 0) has none (pbrt-v3's
// noise).
TEST(TextureClasses, DotsSitWherePbrtV3PutsThem) {
    auto dots = texture("dots", {}, TextureKind::Float);
    expectRgb(dots->evaluate(hitAt(0.03f, 0.93f)), {0, 0, 0});
    expectRgb(dots->evaluate(hitAt(0.03f + 0.33f, 0.93f)), {0, 0, 0});  // 0.3347 from the centre
    expectRgb(dots->evaluate(hitAt(0.03f + 0.36f, 0.93f)), {1, 1, 1});  // beyond the radius 0.35
    expectRgb(dots->evaluate(hitAt(0.0f, 0.0f)), {1, 1, 1});            // no dot in cell (0, 0)
}

}  // namespace
}  // namespace lenslab
