// The spectral realistic camera against closed forms: a dispersion-free lens gives the RGB film's
// picture, a grey card stays grey through a dispersive lens, and a white-on-black edge near the
// frame's corner through a lens with lateral colour splits into a colour fringe as wide as the
// optics' chief rays at each wavelength predict for the film's red and blue channels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "firstorder/ChiefRay.h"
#include "firstorder/FirstOrder.h"
#include "trace/ExactTrace.h"
#include "prescription/LensSystem.h"
#include "TestScenes.h"
#include "core/ColourMatching.h"
#include "core/SmitsSpectrum.h"
#include "core/Spectrum.h"

namespace lenslab {
namespace {

RenderOutput renderSpectral(const std::string& scene, int w, int h, int spp, bool spectral, std::uint64_t seed,
                        std::optional<std::array<double, 4>> crop = std::nullopt, int wavelengthsPerSample = 3) {
    RenderSettings s;
    s.camera.spectral = spectral;
    s.wavelengthsPerSample = wavelengthsPerSample;
    s.seed = seed;
    s.crop = crop;
    return test::render(scene, w, h, spp, s);
}

Vec3f channelMeans(const Image& im) {
    double c[3] = {0, 0, 0};
    for (std::size_t i = 0; i < im.rgb.size(); ++i) c[i % 3] += im.rgb[i];
    const double n = double(im.width) * im.height;
    return {float(c[0] / n), float(c[1] / n), float(c[2] / n)};
}

// RMS over 8x8-pixel blocks and channels of the difference of the block means.
double blockRms(const Image& a, const Image& b) {
    double sum = 0;
    int count = 0;
    for (int by = 0; by + 8 <= a.height; by += 8)
        for (int bx = 0; bx + 8 <= a.width; bx += 8)
            for (int c = 0; c < 3; ++c) {
                double d = 0;
                for (int y = by; y < by + 8; ++y)
                    for (int x = bx; x < bx + 8; ++x) {
                        const std::size_t i = (std::size_t(y) * a.width + x) * 3 + c;
                        d += a.rgb[i] - b.rgb[i];
                    }
                sum += (d / 64) * (d / 64);
                ++count;
            }
    return std::sqrt(sum / count);
}

// Coloured and white cards under a light, through a lens; course parameters.
std::string cards(const std::string& lens) {
    return test::courseCamera(lens, "\"float fstop\" 4 \"float focaldistance\" 3000 \"float filmdiagonal\" 43.3") +
           "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\"\nWorldBegin\n"
           "LightSource \"point\" \"rgb I\" [40 40 40] \"point from\" [0 2 0]\n"
           "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.8 0.15 0.1]\nTranslate -0.6 0 3\nShape \"sphere\" \"float radius\" 0.35\nAttributeEnd\n"
           "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.1 0.7 0.2]\nTranslate 0 0 3\nShape \"sphere\" \"float radius\" 0.35\nAttributeEnd\n"
           "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.15 0.2 0.9]\nTranslate 0.6 0 3\nShape \"sphere\" \"float radius\" 0.35\nAttributeEnd\n"
           "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.9 0.9 0.9]\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-5 -0.4 -1  5 -0.4 -1  5 -0.4 9  -5 -0.4 9]\n"
           "AttributeEnd\nWorldEnd\n";
}

}  // namespace

TEST(SpectralCamera, DispersionFreeLensGivesTheRgbPicture) {
    test::TempDir dir;
    const std::string scene = dir.write("cards.pbrt", cards("dgauss.50mm.dat"));
    const RenderOutput rgb1 = renderSpectral(scene, 64, 48, 16, false, 1), rgb2 = renderSpectral(scene, 64, 48, 16, false, 2);
    const RenderOutput sp1 = renderSpectral(scene, 64, 48, 16, true, 1), sp2 = renderSpectral(scene, 64, 48, 16, true, 2);
    EXPECT_EQ(sp1.metadata.at("film").rfind("spectral", 0), 0u);
    EXPECT_EQ(rgb1.metadata.at("film").rfind("RGB", 0), 0u);
    const Vec3f mRgb = channelMeans(rgb1.image), mSp = channelMeans(sp1.image);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mSp[c] / mRgb[c], 1.0, 0.005) << "channel " << c;
    // The difference of spectral and RGB blocks is what their noise explains: each noise measured
    // from two seeds.
    const double noiseRgb = blockRms(rgb1.image, rgb2.image) / std::sqrt(2.0);
    const double noiseSp = blockRms(sp1.image, sp2.image) / std::sqrt(2.0);
    const double expected = std::hypot(noiseRgb, noiseSp), measured = blockRms(sp1.image, rgb1.image);
    std::printf("block rms: spectral - rgb %.5f, noise floor %.5f (rgb %.5f, spectral %.5f)\n", measured, expected,
                noiseRgb, noiseSp);
    EXPECT_LT(measured, 1.3 * expected);
}

// Through a dispersive lens, several wavelengths per sample (each scored where the lens brings the
// sample's scene ray at that wavelength, weighed against the others' densities) estimate the same
// picture as one: channel means within 1%, blocks within the noise floor of the two.
TEST(SpectralCamera, SeveralWavelengthsPerSampleGiveTheOneWavelengthPicture) {
    test::TempDir dir;
    const std::string scene = dir.write("cards.pbrt", cards("dgauss-glass.dat"));
    const RenderOutput one1 = renderSpectral(scene, 64, 48, 16, true, 1, std::nullopt, 1);
    const RenderOutput one2 = renderSpectral(scene, 64, 48, 16, true, 2, std::nullopt, 1);
    const RenderOutput four1 = renderSpectral(scene, 64, 48, 16, true, 1, std::nullopt, 4);
    const RenderOutput four2 = renderSpectral(scene, 64, 48, 16, true, 2, std::nullopt, 4);
    const Vec3f mOne = channelMeans(one1.image), mFour = channelMeans(four1.image);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mFour[c] / mOne[c], 1.0, 0.01) << "channel " << c;
    const double expected = std::hypot(blockRms(one1.image, one2.image), blockRms(four1.image, four2.image)) / std::sqrt(2.0);
    const double measured = blockRms(four1.image, one1.image);
    std::printf("block rms: 4 wavelengths - 1 %.5f, noise floor %.5f\n", measured, expected);
    EXPECT_LT(measured, 1.3 * expected);
}

// Unless told, a spectral frame takes three wavelengths a sample with a smooth filter and one with
// the box (whose hard borders make the others' moves noisier than they save: bench/README.md).
TEST(SpectralCamera, WavelengthsPerSampleFollowTheFilterUnlessTold) {
    test::TempDir dir;
    const std::string box = cards("dgauss-glass.dat"), boxFilter = "PixelFilter \"box\"";
    const std::string gaussian = std::string(box).replace(box.find(boxFilter), boxFilter.size(), "PixelFilter \"gaussian\"");
    const auto film = [&](const std::string& name, const std::string& scene, int perSample) {
        return renderSpectral(dir.write(name, scene), 16, 12, 1, true, 1, std::nullopt, perSample).metadata.at("film");
    };
    EXPECT_EQ(film("box.pbrt", box, 0).rfind("spectral: wavelengths per sample 1 ", 0), 0u);
    EXPECT_EQ(film("gaussian.pbrt", gaussian, 0).rfind("spectral: wavelengths per sample 3 ", 0), 0u);
    EXPECT_EQ(film("box4.pbrt", box, 4).rfind("spectral: wavelengths per sample 4 ", 0), 0u);
    EXPECT_THROW(film("box9.pbrt", box, 9), SceneError);
}

TEST(SpectralCamera, GreyCardStaysNeutralThroughADispersiveLens) {
    test::TempDir dir;
    const std::string scene = dir.write(
        "grey.pbrt", test::courseCamera("dgauss-glass.dat", "\"float fstop\" 4 \"float focaldistance\" 2000 \"float filmdiagonal\" 43.3") +
                         "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\"\nWorldBegin\n"
                         "LightSource \"distant\" \"rgb L\" [3 3 3] \"point from\" [0 0 0] \"point to\" [0 0 1]\n"
                         "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
                         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-5 -5 2  5 -5 2  5 5 2  -5 5 2]\n"
                         "WorldEnd\n");
    const RenderOutput out = renderSpectral(scene, 96, 64, 32, true, 3);
    ASSERT_NE(out.metadata.at("lensWavelengths").find("each exact ray"), std::string::npos);
    const Vec3f m = channelMeans(out.image);
    const double mean = (m.x + m.y + m.z) / 3;
    ASSERT_GT(mean, 0.005);
    double chroma = 0;
    for (int c = 0; c < 3; ++c) chroma = std::max(chroma, std::fabs(m[c] - mean) / mean);
    std::printf("grey card: rgb %.5f %.5f %.5f, chroma %.4f%%\n", m.x, m.y, m.z, 100 * chroma);
    EXPECT_LT(chroma, 0.01);
}

// A plano-convex N-BK7-like singlet (model glass nd 1.5168, Vd 64.17, EFL about 100 mm) behind a
// stop 20 mm in front of it: the remote stop gives it strong lateral colour (about f / Vd tan theta).
const char* kSingletBehindStop =
    "# radius gap N diameter glass (gap before)\n"
    "0      0   0       12.5\n"
    "51.68  20  1.5168  30  64.17\n"
    "0      5   1       30\n";

// A glowing half-plane 100 m ahead whose edge runs across the frame's diagonal at 3/4 of the
// half-diagonal, white on the outer side. Each channel's edge position (the area method: where a
// sharp edge of the same total light would lie) is measured along the diagonal; the optics
// predicts it as the channel's average over wavelength of the chief ray's height, weighted by the
// channel's response to a white spectrum at that wavelength.
class LateralColourFringe : public ::testing::TestWithParam<int> {};

TEST_P(LateralColourFringe, FringeMatchesTheChiefRays) {
    test::TempDir dir;
    const std::string lensFile = dir.write("singlet.dat", kSingletBehindStop);
    const int width = 2400, height = 1600;
    const double diagonalMm = 43.3, pixelMm = diagonalMm / std::hypot(width, height), distanceM = 100;
    const double imageHeightMm = 0.75 * 0.5 * diagonalMm;
    const LensSystem lens = loadLensSystem(lensFile);
    const double tanField = imageHeightMm / computeFirstOrder(lens).efl;

    // The diagonal toward the top right corner: (ux, uy) in the world and in the picture (y up).
    const double ux = width / std::hypot(width, height), uy = height / std::hypot(width, height);
    const double s0 = distanceM * tanField, s1 = s0 + 30, t = 30;  // the white side, along and across the diagonal
    const auto corner = [&](double s, double q) {
        return std::to_string(s * ux - q * uy) + " " + std::to_string(s * uy + q * ux) + " " + std::to_string(distanceM);
    };
    const std::string scene = dir.write(
        "edge.pbrt",
        "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"" + lensFile +
            "\" \"float fstop\" 8 \"float focaldistance\" 100000 \"float filmdiagonal\" " + std::to_string(diagonalMm) +
            "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\"\nWorldBegin\n"
            "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" \"true\"\n"
            "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [" +
            corner(s0, -t) + "  " + corner(s1, -t) + "  " + corner(s1, t) + "  " + corner(s0, t) + "]\nWorldEnd\n");

    // The film plane the camera focuses on, and each wavelength's chief-ray height on it.
    const RenderOutput probe = renderSpectral(scene, width, height, 1, true, 0, std::array<double, 4>{0.5, 0.501, 0.5, 0.501});
    const double filmZ = std::stod(probe.metadata.at("filmZMm"));
    const double fieldDeg = std::atan(tanField) * 180 / M_PI;
    const auto chiefHeight = [&](double nm) {
        const LensSystem l = atWavelength(lens, nm);
        const Ray in = *chiefRay(l, fieldDeg);
        const Ray out = traceRay(l, in, TraceDirection::SceneToFilm).ray;
        return std::fabs(out.origin.y + (filmZ - out.origin.z) / out.direction.z * out.direction.y);
    };
    double predicted[3] = {0, 0, 0}, weight[3] = {0, 0, 0};
    for (int nm = kVisibleFirstNm; nm <= kVisibleLastNm; ++nm) {
        const double white = smitsBasis(SmitsBasis::White, nm);
        const Vec3f w = xyzToRgb(white * cieX(nm), white * cieY(nm), white * cieZ(nm));
        const double h = chiefHeight(nm);
        for (int c = 0; c < 3; ++c) predicted[c] += w[c] * h, weight[c] += w[c];
    }
    for (int c = 0; c < 3; ++c) predicted[c] /= weight[c];
    const double predictedFringe = predicted[0] - predicted[2];

    // Render 128 x 128 pixels around the d edge and measure each channel's edge along the diagonal.
    const double hD = chiefHeight(lens.wavelength) / pixelMm;
    const double cx = width / 2.0 + hD * ux, cy = height / 2.0 - hD * uy, half = 64;
    const RenderOutput out = renderSpectral(scene, width, height, 64, true, 5,
                                        std::array<double, 4>{(cx - half) / width, (cx + half) / width,
                                                              (cy - half) / height, (cy + half) / height},
                                        GetParam());
    const Image& im = out.image;
    const int x0 = int(std::ceil(cx - half)), y0 = int(std::ceil(cy - half));
    constexpr int kBins = 160;  // half-pixel bins along the diagonal, from 40 pixels inside to 40 outside
    std::vector<double> sum(kBins * 3, 0), count(kBins, 0);
    const double rhoEdge = chiefHeight(lens.wavelength) / pixelMm;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double px = x0 + x + 0.5 - width / 2.0, py = -(y0 + y + 0.5 - height / 2.0);
            const double along = px * ux + py * uy - rhoEdge, across = py * ux - px * uy;
            const int bin = int(std::floor((along + 40) * 2));
            if (std::fabs(across) > 12 || bin < 0 || bin >= kBins) continue;
            for (int c = 0; c < 3; ++c) sum[bin * 3 + c] += im.rgb[(std::size_t(y) * im.width + x) * 3 + c];
            count[bin] += 1;
        }
    double edge[3];
    for (int c = 0; c < 3; ++c) {
        double whiteLevel = 0, whiteBins = 0, area = 0;
        for (int b = kBins - 10; b < kBins; ++b) whiteLevel += sum[b * 3 + c] / count[b], whiteBins += 1;
        whiteLevel /= whiteBins;
        for (int b = 0; b < kBins; ++b) area += sum[b * 3 + c] / count[b] / whiteLevel * 0.5;
        edge[c] = (40 - area) * pixelMm + rhoEdge * pixelMm;  // mm from the frame's centre
    }
    const double measuredFringe = edge[0] - edge[2];
    std::printf("edge at %.3f mm (%.2f deg): R %.5f  G %.5f  B %.5f mm; fringe R-B measured %.5f mm, "
                "predicted %.5f mm (chief rays, R %.5f B %.5f)\n",
                imageHeightMm, fieldDeg, edge[0], edge[1], edge[2], measuredFringe, predictedFringe, predicted[0], predicted[2]);
    ASSERT_GT(std::fabs(predictedFringe), 2 * pixelMm / 10) << "the lens must show a measurable fringe";
    EXPECT_NEAR(measuredFringe / predictedFringe, 1.0, 0.2);
}

// One wavelength per sample, and several sharing each sample's scene path (docs/spectral.md).
INSTANTIATE_TEST_SUITE_P(SpectralCamera, LateralColourFringe, ::testing::Values(1, 2, 4, 8));

}  // namespace lenslab
