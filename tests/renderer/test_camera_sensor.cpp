// The real sensor behind the film (film/SensorReadout.h): its calibration against the published
// constants it is built on, its noise against the photon-transfer relations a sensor is measured
// by (EMVA 1288), and a render through a lens against the lens's f-number.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>


#include "film/SensorReadout.h"
#include "sampling/Sampling.h"
#include "settings/LensAnalysis.h"
#include "cameras/RealisticCamera.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// A sensor with every noise off but the photons' own, read through a fine ADC.
SensorSpec shotOnly() {
    SensorSpec s;
    s.readNoiseElectrons = 0;
    s.darkCurrentElectronsPerSecond = 0;
    s.dsnuElectronsPerSecond = 0;
    s.prnu = 0;
    s.adcBits = 24;
    s.gainElectronsPerDn = 0.01;
    s.fullWellElectrons = 1e9;
    s.exposureSeconds = 1;
    return s;
}

// 4 um pixels behind a film whose values are focal-plane exposure in lux s (nits 1, 1 s).
const SensorExposureInput kUnitFilm{1.0, 1.0, 4.0, 0.0};

Image flat(int w, int h, float value) {
    Image im;
    im.width = w;
    im.height = h;
    im.rgb.assign(std::size_t(w) * h * 3, value);
    return im;
}

struct Moments {
    double mean = 0, variance = 0;
};

// Over every pixel's green channel, in electrons (the output over its value per electron).
Moments electronMoments(const Image& im, const SensorCalibration& c) {
    const double perElectron = c.outputPerLuxSecond / c.electronsPerLuxSecond;
    double sum = 0, squares = 0;
    const std::size_t n = std::size_t(im.width) * im.height;
    for (std::size_t i = 0; i < n; ++i) {
        const double e = im.rgb[i * 3 + 1] / perElectron;
        sum += e;
        squares += e * e;
    }
    const double mean = sum / n;
    return {mean, squares / n - mean * mean};
}

// The variance of the difference of two frames over two: the temporal noise alone, the fixed pattern cancelled.
double temporalVariance(const Image& a, const Image& b, const SensorCalibration& c) {
    const double perElectron = c.outputPerLuxSecond / c.electronsPerLuxSecond;
    double sum = 0, squares = 0;
    const std::size_t n = std::size_t(a.width) * a.height;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = (a.rgb[i * 3 + 1] - b.rgb[i * 3 + 1]) / perElectron;
        sum += d;
        squares += d * d;
    }
    const double mean = sum / n;
    return 0.5 * (squares / n - mean * mean);
}

// A frame exposed to `electrons` per photosite on average.
Image exposed(const SensorSpec& s, const SensorCalibration& c, double electrons, std::uint64_t seed, int side = 200) {
    Image im = flat(side, side, float(electrons / (c.luxSecondsPerValue * c.electronsPerLuxSecond)));
    readOutSensor(s, c, seed, 0, 0, im);
    return im;
}

TEST(CameraSensor, ElectronsPerLuxSecondFollowFromThePhotonsOf555nmLight) {
    // One lux at 555 nm is 1/683 W/m^2: 4.0906e15 photons per second and square metre.
    SensorSpec s = shotOnly();
    s.quantumEfficiency = 0.5;
    s.fillFactor = 0.8;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    EXPECT_NEAR(c.electronsPerLuxSecond, 0.5 * 0.8 * 16e-12 * 4.0906e15, 0.0002 * c.electronsPerLuxSecond);
    // The full well scales with the pixel's area unless given: 2,700 e- per square micrometre.
    SensorSpec d;
    const SensorCalibration dc = calibrateSensor(d, kUnitFilm);
    EXPECT_DOUBLE_EQ(dc.fullWellElectrons, 2700 * 16);
    // The base ISO: 78 lux s over ISO just fills the well (QE 0.5, fill 1: 32,725 e- per lux s).
    EXPECT_NEAR(dc.baseIso, 78 * 0.5 * 16e-12 * 4.0906e15 / (2700 * 16), 0.01);
}

TEST(CameraSensor, ShotLimitedSignalToNoiseIsTheRootOfTheElectrons) {
    const SensorSpec s = shotOnly();
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    const Moments m = electronMoments(exposed(s, c, 10000, 7), c);
    EXPECT_NEAR(m.mean, 10000, 3);
    const double snrDb = 20 * std::log10(m.mean / std::sqrt(m.variance));
    EXPECT_NEAR(snrDb, 40.0, 0.1);  // 40,000 samples: the variance's own scatter is 0.7%, 0.03 dB
}

TEST(CameraSensor, PhotonTransferCurveHasSlopeOneOverGainAndTheReadNoiseAsIntercept) {
    SensorSpec s = shotOnly();
    s.gainElectronsPerDn = 2.0;
    s.readNoiseElectrons = 6.0;
    s.adcBits = 16;
    s.blackLevelDn = 1024;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    // Mean and variance in DN above black, fitted by least squares: the slope over 200 to 80,000 e-,
    // the intercept over 0 to 1,600 e- (where the variances' own scatter is below a DN^2).
    const auto fit = [&](std::initializer_list<double> levels, double& slope, double& intercept) {
        std::vector<double> means, variances;
        for (double electrons : levels) {
            const Moments m = electronMoments(exposed(s, c, electrons, 11), c);
            means.push_back(m.mean / 2.0);
            variances.push_back(m.variance / 4.0);
        }
        double mx = 0, my = 0;
        for (std::size_t i = 0; i < means.size(); ++i) {
            mx += means[i] / means.size();
            my += variances[i] / means.size();
        }
        double sxy = 0, sxx = 0;
        for (std::size_t i = 0; i < means.size(); ++i) {
            sxy += (means[i] - mx) * (variances[i] - my);
            sxx += (means[i] - mx) * (means[i] - mx);
        }
        slope = sxy / sxx;
        intercept = my - slope * mx;
    };
    double slope = 0, intercept = 0;
    fit({200.0, 1000.0, 3000.0, 6000.0, 10000.0, 20000.0, 40000.0, 80000.0}, slope, intercept);
    EXPECT_NEAR(slope, 1 / 2.0, 0.005);
    fit({0.0, 100.0, 200.0, 400.0, 800.0, 1600.0}, slope, intercept);
    EXPECT_NEAR(slope, 1 / 2.0, 0.01);
    // (6 e- / 2 e-/DN)^2 = 9 DN^2, and a whole-DN ADC's rounding, 1/12.
    EXPECT_NEAR(intercept, 9 + 1.0 / 12, 0.6);
}

TEST(CameraSensor, FlatFieldShowsThePixelResponseNonUniformity) {
    SensorSpec s = shotOnly();
    s.prnu = 0.01;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    const Image a = exposed(s, c, 40000, 1), b = exposed(s, c, 40000, 2);
    const double total = electronMoments(a, c).variance, temporal = temporalVariance(a, b, c);
    EXPECT_NEAR(temporal, 40000, 40000 * 0.03);       // shot noise alone
    EXPECT_NEAR(std::sqrt(total - temporal) / 40000, 0.01, 0.0006);  // the fixed pattern: PRNU
    // The pattern is the sensor's: another pattern seed, another pattern; the same seed, the same frame.
    SensorSpec other = s;
    other.patternSeed = 9;
    const Image c2 = exposed(other, c, 40000, 2);
    EXPECT_NEAR(temporalVariance(a, c2, c), 40000 + 40000.0 * 40000 * 1e-4, 0.06 * (40000 + 160000));
    EXPECT_EQ(exposed(s, c, 40000, 1).rgb, a.rgb);
}

TEST(CameraSensor, DarkFramesCarryDarkCurrentAndItsNonUniformity) {
    SensorSpec s = shotOnly();
    s.exposureSeconds = 10;
    s.darkCurrentElectronsPerSecond = 5;
    s.dsnuElectronsPerSecond = 1;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    const Image a = exposed(s, c, 0, 3), b = exposed(s, c, 0, 4);
    const Moments m = electronMoments(a, c);
    EXPECT_NEAR(m.mean, 50, 0.25);
    EXPECT_NEAR(temporalVariance(a, b, c), 50, 2.5);          // the dark signal's shot noise
    EXPECT_NEAR(m.variance - temporalVariance(a, b, c), 100, 8);  // DSNU: (1 e-/s x 10 s)^2
}

TEST(CameraSensor, FullWellClipsAndStandardOutputSensitivitySetsTheLevels) {
    // ISO 12232: 10 / ISO lux s reads 0.18; the ADC's full scale is reached at 78 / ISO lux s.
    for (double iso : {400.0, 3200.0}) {
        SensorSpec s;
        s.iso = iso;
        s.readNoiseElectrons = 0;
        s.prnu = 0;
        s.darkCurrentElectronsPerSecond = 0;
        s.dsnuElectronsPerSecond = 0;
        s.exposureSeconds = 1;
        const SensorCalibration c = calibrateSensor(s, kUnitFilm);
        Image grey = flat(100, 100, float(10 / iso));
        readOutSensor(s, c, 5, 0, 0, grey);
        EXPECT_NEAR(test::meanLum(grey), 0.18, 0.18 * 0.003) << "ISO " << iso;
        Image bright = flat(10, 10, float(2 * 78 / iso));
        const SensorReadoutStats stats = readOutSensor(s, c, 5, 0, 0, bright);
        EXPECT_NEAR(bright.rgb[0], 0.018 * 78, 1e-3) << "ISO " << iso;
        EXPECT_EQ(stats.adcClipped, 300u);
        EXPECT_EQ(stats.wellClipped, 0u);  // above the base ISO the ADC clips first
    }
    // Below the base ISO the well fills first: its electrons are the brightest output.
    SensorSpec low;
    low.iso = 25;
    low.readNoiseElectrons = 0;
    low.exposureSeconds = 1;
    const SensorCalibration c = calibrateSensor(low, kUnitFilm);
    ASSERT_LT(low.iso, c.baseIso);
    Image bright = flat(10, 10, 10.0f);
    const SensorReadoutStats stats = readOutSensor(low, c, 5, 0, 0, bright);
    EXPECT_EQ(stats.wellClipped, 300u);
    EXPECT_NEAR(bright.rgb[0], c.fullWellElectrons / c.electronsPerLuxSecond * 0.018 * 25, 2e-3);
}

TEST(CameraSensor, TheAdcQuantisesToItsBits) {
    SensorSpec s = shotOnly();
    s.adcBits = 8;
    s.gainElectronsPerDn.reset();
    s.blackLevelDn = 0;
    s.iso = 400;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    EXPECT_NEAR(c.gainElectronsPerDn, 78 / 400.0 * c.electronsPerLuxSecond / 255, 1e-9 * c.gainElectronsPerDn);
    Image im = flat(50, 50, float(4 / 400.0));
    readOutSensor(s, c, 1, 0, 0, im);
    const double step = c.gainElectronsPerDn * c.outputPerLuxSecond / c.electronsPerLuxSecond;
    for (float v : im.rgb) ASSERT_NEAR(v / step, std::round(v / step), 1e-3);
}

TEST(CameraSensor, MeteredExposurePutsTheMeanLuminanceAtEighteenPercent) {
    SensorSpec s;
    s.iso = 800;
    const SensorExposureInput input{0.05, 0.5, 4.0, 0.3};  // 0.05 sr s per value over a 0.5 s shutter
    const SensorCalibration c = calibrateSensor(s, input);
    EXPECT_NEAR(c.exposureSeconds, 0.5 * 10 / (800 * 0.3 * 0.05), 1e-12);
    Image im = flat(100, 100, 0.3f);
    readOutSensor(s, c, 3, 0, 0, im);
    EXPECT_NEAR(test::meanLum(im), 0.18, 0.002);
}

TEST(CameraSensor, KeysAreCheckedByName) {
    const auto error = [](const std::string& text) {
        try {
            sensorSpecFromPairs(parseSensorPairs(text));
        } catch (const SensorSpecError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(sensorSpecFromPairs(parseSensorPairs("iso=3200,exposure=0.004,bits=12")).adcBits, 12);
    EXPECT_NE(error("iso=0").find("iso must be between 1 and"), std::string::npos) << error("iso=0");
    EXPECT_NE(error("isp=100").find("unknown key 'isp'"), std::string::npos);
    EXPECT_NE(error("iso=100,iso=200").find("iso is given twice"), std::string::npos);
    EXPECT_NE(error("bits=12.5").find("bits must be a whole number"), std::string::npos);
    EXPECT_NE(error("iso=fast").find("'fast' is not a number"), std::string::npos);
    EXPECT_NE(error("iso").find("is not key=value"), std::string::npos);
    EXPECT_NE(error("bits=10,black=1023").find("must lie below the 10-bit full scale 1023"), std::string::npos);
    EXPECT_NE(error("prnu=nan").find("prnu must be between"), std::string::npos);
}

// A uniform sky seen through dgauss.50mm at f/8 focused far away.
std::string skyScene(const std::string& camera) {
    return camera + "\nFilm \"image\"\nPixelFilter \"box\"\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\nWorldEnd\n";
}

TEST(CameraSensor, ThroughALensTheCentreCollectsTheProjectedSolidAngleThatPasses) {
    // E / L = integral of cos dw over the directions from the film's centre that pass the lens,
    // found here by tracing a cosine-weighted cone through the exact lens; at L = 1000 cd/m^2 and
    // 1/30 s (the sensor's, not the scene's half-second shutter) the centre reads 0.018 ISO times
    // E t. The f-number alone (pi / (4 N^2), the marginal
    // ray's from infinity) agrees to 0.5%.
    test::TempDir dir;
    const std::string scene = dir.write("sky.pbrt", skyScene(test::courseCamera("dgauss.50mm.dat",
        "\"float fstop\" 8 \"float focaldistance\" 1e6 \"float filmdiagonal\" 5 \"float shutteropen\" 0 \"float shutterclose\" 0.5")));
    RenderSettings s;
    s.sensor = sensorSpecFromPairs(parseSensorPairs("iso=100,exposure=0.0333333333333,nits=1000,read=0,prnu=0,dark=0,dsnu=0"));
    // 4,096 lens samples over the central 0.8 mm: 2% of the sampled pupil region is blocked at
    // f/8, which they estimate to 0.22%.
    const RenderOutput out = test::render(scene, 40, 30, 64, s);
    double centre = 0;
    for (int y = 11; y < 19; ++y)
        for (int x = 16; x < 24; ++x) centre += test::lum(out.image, x, y) / 64;

    const LensAnalysis a = analyzeLens(loadLensSystem(test::lensPath("dgauss.50mm.dat")), 8.0, 1e6);
    const double sinMax = std::sin(8 * M_PI / 180);
    const int m = 600;
    RayBatch batch;
    batch.resize(std::size_t(m) * m);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            float dx, dy;
            concentricDisk(float((i + 0.5) / m), float((j + 0.5) / m), dx, dy);
            const double x = sinMax * dx, y = sinMax * dy;
            batch.set(std::size_t(j) * m + i, {Vec3{0, 0, a.focus.imageZExact}, Vec3{x, y, std::sqrt(1 - x * x - y * y)}});
        }
    traceBatch(a.lens, batch, TraceDirection::FilmToScene);
    const std::size_t passed = std::count(batch.blocked.begin(), batch.blocked.end(), BlockReason::None);
    const double projectedSolidAngle = M_PI * sinMax * sinMax * double(passed) / (double(m) * m);
    const double expected = 0.018 * 100 * 1000 * projectedSolidAngle / 30;
    EXPECT_NEAR(centre, expected, 0.008 * expected);
    EXPECT_NEAR(projectedSolidAngle / (M_PI / (4 * 64)), 1.0, 0.006);
    EXPECT_NE(out.metadata.at("sensor").find("ISO 100, exposure 0.0333333 s"), std::string::npos) << out.metadata.at("sensor");
    // The film's pitch: its 5 mm diagonal over the 50-pixel diagonal.
    EXPECT_NE(out.metadata.at("sensor").find("pitch 100 um"), std::string::npos) << out.metadata.at("sensor");
}

TEST(CameraSensor, NoiseBelongsToTheFullFramesPixelsAndAPitchSetsTheFilm) {
    test::TempDir dir;
    const std::string scene = dir.write("sky.pbrt", skyScene(test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 4")));
    RenderSettings s;
    // 35 mm over 50 px; an exposure given, since a metered one meters the rendered (cropped) part.
    s.sensor = sensorSpecFromPairs(parseSensorPairs("iso=25600,pitch=700,exposure=0.0001"));
    const RenderOutput full = test::render(scene, 40, 30, 2, s);
    s.crop = std::array<double, 4>{0.5, 1, 0.5, 1};
    const RenderOutput crop = test::render(scene, 40, 30, 2, s);
    ASSERT_EQ(crop.image.width, 20);
    for (int y = 0; y < 15; ++y)
        for (int x = 0; x < 20; ++x)
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_EQ(crop.image.rgb[(std::size_t(y) * 20 + x) * 3 + ch],
                          full.image.rgb[(std::size_t(y + 15) * 40 + x + 20) * 3 + ch]);
    s.crop.reset();
    s.camera.filmDiagonal = 24;
    EXPECT_THROW(test::render(scene, 40, 30, 1, s), SceneError);
}

TEST(CameraSensor, APinholeHasNoExposureToRead) {
    test::TempDir dir;
    const std::string scene = dir.write("p.pbrt", skyScene("Camera \"perspective\""));
    RenderSettings s;
    s.sensor = SensorSpec{};
    s.scenePath = scene;
    try {
        checkRenderSettings(s);
        FAIL() << "a perspective camera took a sensor";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("the sensor needs a lens"), std::string::npos) << e.what();
    }
    EXPECT_THROW(test::render(scene, 8, 8, 1, s), SceneError);
}

}  // namespace
}  // namespace lenslab
