// pbrt-v4's measured camera sensors (film/MeasuredCameraSensor.h) against sums of the published curves
// done here: the colour fit over the ColorChecker swatches, its white balance, a rendered wall.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "TestScenes.h"
#include "core/CameraSensorCurves.h"
#include "core/ColourCheckerSwatches.h"
#include "core/ColourMatching.h"
#include "core/DaylightSpectrum.h"
#include "core/Spectrum.h"
#include "film/MeasuredCameraSensor.h"

namespace lenslab {
namespace {

constexpr double kWhiteBalance = 5000;  // clouds' and bunny-cloud's

// pbrt-v4's sensor illuminant for 5000 K: daylight at 5000 x 1.4388 / 1.4380 K.
double illuminant(double nm) { return daylightSpectrum(kWhiteBalance * 1.4388 / 1.4380, nm); }
double d65(double nm) { return daylightSpectrum(6504, nm); }

// A spectrum against three weighting functions, summed at whole nm over pbrt-v4's 360-830 nm.
template <typename F, typename A, typename B, typename C>
Triple integrate(F spectrum, A a, B b, C c) {
    Triple t{0, 0, 0};
    for (int nm = 360; nm <= 830; ++nm) {
        t[0] += a(nm) * spectrum(nm);
        t[1] += b(nm) * spectrum(nm);
        t[2] += c(nm) * spectrum(nm);
    }
    return t;
}

const CameraSensorCurves& d850() { return *findCameraSensorCurves("nikon_d850"); }

template <typename F>
Triple cameraRgb(F spectrum) {
    const CameraSensorCurves& s = d850();
    return integrate(spectrum, s.r, s.g, s.b);
}
template <typename F>
Triple xyz(F spectrum) {
    return integrate(spectrum, [](double nm) { return cieX(nm); }, [](double nm) { return cieY(nm); },
                     [](double nm) { return cieZ(nm); });
}

TEST(MeasuredCameraSensor, MatrixIsTheLeastSquaresFitOfTheSwatches) {
    const MeasuredCameraSensor sensor(d850(), kWhiteBalance);
    const Matrix3& m = sensor.xyzFromSensorRgb();
    // pbrt-v4's training pairs: sensor RGB under the illuminant over the illuminant's green, and
    // XYZ under D65 at the illuminant's luminance.
    const double g = cameraRgb(illuminant)[1], y = xyz(illuminant)[1], y65 = xyz(d65)[1];
    double gradient[9] = {}, residual2 = 0, target2 = 0, scale = 0;
    for (int i = 0; i < kColourCheckerSwatches; ++i) {
        const TabulatedSpectrum swatch = colourCheckerSwatch(i);
        Triple a = cameraRgb([&](double nm) { return swatch(nm) * illuminant(nm); });
        Triple b = xyz([&](double nm) { return swatch(nm) * d65(nm); });
        for (int c = 0; c < 3; ++c) a[c] /= g, b[c] *= y / (y65 * g);
        const Triple fit = applyMatrix(m, a);
        for (int r = 0; r < 3; ++r) {
            residual2 += (fit[r] - b[r]) * (fit[r] - b[r]);
            target2 += b[r] * b[r];
            for (int c = 0; c < 3; ++c) {
                gradient[r * 3 + c] += (fit[r] - b[r]) * a[c];
                scale += std::fabs(b[r] * a[c]);
            }
        }
    }
    // The optimum: the residual is orthogonal to every sensor channel.
    for (double v : gradient) EXPECT_NEAR(v / scale, 0, 1e-9);
    // The D850's colour error over the chart: 3.05% of the XYZ (RMS over the swatches).
    EXPECT_NEAR(std::sqrt(residual2 / target2), 0.0305, 0.0005);
}

TEST(MeasuredCameraSensor, TheBalancedIlluminantComesOutWhite) {
    const MeasuredCameraSensor sensor(d850(), kWhiteBalance);
    const Triple white = applyMatrix(sensor.xyzFromSensorRgb(), cameraRgb(illuminant));
    const double sum = white[0] + white[1] + white[2];
    // D65's chromaticity, 0.3127 0.3290, to the fit's error (measured 0.3127 0.3312), at the
    // illuminant's own luminance (measured 0.993 of it).
    EXPECT_NEAR(white[0] / sum, 0.3127, 0.001);
    EXPECT_NEAR(white[1] / sum, 0.3290, 0.003);
    EXPECT_NEAR(white[1] / xyz(illuminant)[1], 1, 0.01);
    // Through the film: the illuminant's CIE colour (yellowish, 1.17 0.98 0.72) becomes neutral
    // to the same error (measured 0.983 1.003 0.978).
    const Triple c = xyz(illuminant);
    const double n = c[1];
    const Vec3f film = sensor.toFilm(xyzToRgb(c[0] / n, 1, c[2] / n));
    EXPECT_NEAR(film.x / film.y, 1, 0.03);
    EXPECT_NEAR(film.z / film.y, 1, 0.03);
}

TEST(MeasuredCameraSensor, AGreyWallRendersAsTheCameraSeesDaylight) {
    test::TempDir dir;
    const auto wall = [&](const std::string& sensor) {
        return test::render(dir.write(sensor + ".pbrt",
            "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"orthographic\"\n"
            "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4 \"string sensor\" \"" + sensor + "\"" +
            (sensor == "cie1931" ? "" : " \"float whitebalance\" 5000") + "\n"
            "Integrator \"path\" \"integer maxdepth\" 1\nWorldBegin\n"
            "LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0 0 0] \"float illuminance\" 3\n"
            "Material \"diffuse\" \"rgb reflectance\" [ .5 .5 .5 ]\n"
            "Shape \"bilinearmesh\" \"point3 P\" [ -10 -10 0  10 -10 0  -10 10 0  10 10 0 ]\n"), 4, 4, 4).image;
    };
    const Image observer = wall("cie1931"), camera = wall("nikon_d850");
    // The wall's light is white: D65 in pbrt-v4, whose camera RGB the fitted matrix takes to XYZ.
    const MeasuredCameraSensor sensor(d850(), kWhiteBalance);
    const Triple seen = applyMatrix(sensor.xyzFromSensorRgb(), cameraRgb(d65));
    const double y65 = xyz(d65)[1];
    const Vec3f expected = xyzToRgb(seen[0] / y65, seen[1] / y65, seen[2] / y65);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(camera.rgb[c] / observer.rgb[c], expected[c], 0.003 * expected[c]) << c;
        EXPECT_NEAR(camera.rgb[c + 3 * 5], camera.rgb[c], 1e-6);  // every pixel alike
    }
    // The observer's luminance to the fit's error (measured 1.011 in green); balanced for 5000 K,
    // the camera sees D65 blue: more blue than green, less red.
    EXPECT_NEAR(camera.rgb[1] / observer.rgb[1], 1, 0.02);
    EXPECT_GT(expected.z, 1.2f * expected.y);
    EXPECT_LT(expected.x, 0.85f * expected.y);
}

TEST(MeasuredCameraSensor, EveryNamedCameraFitsTheChart) {
    std::stringstream names(cameraSensorNames());
    std::string name;
    int count = 0;
    while (std::getline(names, name, ',')) {
        if (name.front() == ' ') name.erase(0, 1);
        const CameraSensorCurves* curves = findCameraSensorCurves(name);
        ASSERT_NE(curves, nullptr) << name;
        const MeasuredCameraSensor sensor(*curves, 6500);
        const Vec3f white = sensor.toFilm({1, 1, 1});  // D65 balanced for 6500 K: about neutral
        EXPECT_NEAR(white.x / white.y, 1, 0.05) << name;
        EXPECT_NEAR(white.z / white.y, 1, 0.05) << name;
        ++count;
    }
    EXPECT_EQ(count, 17);  // pbrt-v4's list
}

TEST(MeasuredCameraSensor, AnUnknownSensorIsRefusedWithTheKnownOnes) {
    test::TempDir dir;
    const std::string error = test::sceneErrorOf(dir.write("s.pbrt",
        "Camera \"perspective\"\nFilm \"rgb\"\n  \"string sensor\" \"nikon_d851\"\nWorldBegin\n"
        "LightSource \"distant\" \"float illuminance\" 3\n"));
    EXPECT_NE(error.find("s.pbrt:2"), std::string::npos) << error;
    EXPECT_NE(error.find("unknown sensor \"nikon_d851\""), std::string::npos) << error;
    for (const char* known : {"cie1931", "nikon_d850", "canon_eos_5d_mkiv", "sony_ilce_9"})
        EXPECT_NE(error.find(known), std::string::npos) << known << ": " << error;
}

}  // namespace
}  // namespace lenslab
