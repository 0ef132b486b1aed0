// The real sensor behind the film (film/SensorReadout.h): its calibration against the published
// constants it is built on, its noise against the photon-transfer relations a sensor is measured
// by (EMVA 1288), and a render through a lens against the lens's f-number. Its Bayer mosaic: the
// sites' colours, their noise, the demosaiced picture, and the DNG file read back by LibRaw.
#include <gtest/gtest.h>
#include <libraw.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "film/Demosaic.h"
#include "film/SensorReadout.h"
#include "settings/LensAnalysis.h"
#include "cameras/RealisticCamera.h"
#include "PassingSolidAngle.h"
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

// A sensor measured by its photon transfer: 2 e-/DN, 6 e- read noise, a 16-bit ADC, black 1,024 DN.
SensorSpec photonTransferSensor() {
    SensorSpec s = shotOnly();
    s.gainElectronsPerDn = 2.0;
    s.readNoiseElectrons = 6.0;
    s.adcBits = 16;
    s.blackLevelDn = 1024;
    return s;
}

// The message of the SensorSpecError that the command line's text gives, or "(no error)".
std::string sensorKeyError(const std::string& text) {
    try {
        sensorSpecFromPairs(parseSensorPairs(text));
    } catch (const SensorSpecError& e) {
        return std::string(e.what());
    }
    return std::string("(no error)");
}

TEST(CameraSensor, PhotonTransferCurveHasSlopeOneOverGainAndTheReadNoiseAsIntercept) {
    const SensorSpec s = photonTransferSensor();
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
        const SensorReadout stats = readOutSensor(s, c, 5, 0, 0, bright);
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
    const SensorReadout stats = readOutSensor(low, c, 5, 0, 0, bright);
    EXPECT_EQ(stats.wellClipped, 300u);
    EXPECT_NEAR(bright.rgb[0], c.fullWellElectrons / c.electronsPerLuxSecond * 0.018 * 25, 2e-3);
}

// Light far past the full well (the service's finding: nits 1e12, 1 s; nits 1e9 at 1000 s through
// 1 mm pixels) puts a Poisson mean past 2^63, where the standard sampler rejected every draw and the
// render's worker spun for good (a 16 x 12 frame of a 35 mm film has 2.2 mm pixels). Such sites read
// full; a well of the largest allowed capacity still draws its own noise, and an infinite film value
// reads full too.
TEST(CameraSensor, LightFarPastTheFullWellReadsFullAtOnce) {
    for (const SensorPairs& pairs : {SensorPairs{{"nits", 1e12}, {"exposure", 1.0}},
                                     SensorPairs{{"nits", 1e9}, {"exposure", 1e3}, {"pitch", 1000.0}}}) {
        const SensorSpec s = sensorSpecFromPairs(pairs);
        const double pitch = s.pitchMicrometres.value_or(2163);
        const SensorCalibration c = calibrateSensor(s, {kUnitFilm.exposurePerValue, 1.0, pitch, 0.0});
        Image im = flat(16, 12, 1.0f);
        ASSERT_GT(c.luxSecondsPerValue * c.electronsPerLuxSecond, 0x1p63);
        const SensorReadout stats = readOutSensor(s, c, 7, 0, 0, im);
        EXPECT_EQ(stats.wellClipped, 16u * 12u * 3u);
        for (float v : im.rgb) ASSERT_TRUE(std::isfinite(v));
    }
    SensorSpec deep = shotOnly();
    deep.fullWellElectrons = 1e12;
    deep.gainElectronsPerDn = 1e6;
    const SensorCalibration c = calibrateSensor(deep, kUnitFilm);
    const double perValue = c.luxSecondsPerValue * c.electronsPerLuxSecond;
    Image im = flat(20, 20, float(0.999e12 / perValue));
    im.rgb[0] = std::numeric_limits<float>::infinity();
    const SensorReadout stats = readOutSensor(deep, c, 9, 0, 0, im);
    EXPECT_EQ(stats.wellClipped, 1u);
    const Moments m = electronMoments(im, c);
    EXPECT_NEAR(m.mean, 0.999e12, 1e-6 * 1e12);
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
    EXPECT_EQ(sensorSpecFromPairs(parseSensorPairs("iso=3200,exposure=0.004,bits=12")).adcBits, 12);
    EXPECT_NE(sensorKeyError("iso=0").find("iso must be between 1 and"), std::string::npos) << sensorKeyError("iso=0");
    EXPECT_NE(sensorKeyError("isp=100").find("unknown key 'isp'"), std::string::npos);
    EXPECT_NE(sensorKeyError("iso=100,iso=200").find("iso is given twice"), std::string::npos);
    EXPECT_NE(sensorKeyError("bits=12.5").find("bits must be a whole number"), std::string::npos);
    EXPECT_NE(sensorKeyError("bits=16.0000001").find("got 16.0000001"), std::string::npos) << sensorKeyError("bits=16.0000001");
    EXPECT_NE(sensorKeyError("iso=fast").find("'fast' is not a number"), std::string::npos);
    EXPECT_NE(sensorKeyError("iso").find("is not key=value"), std::string::npos);
    EXPECT_NE(sensorKeyError("bits=10,black=1023").find("must lie below the 10-bit full scale 1023"), std::string::npos);
    EXPECT_NE(sensorKeyError("prnu=nan").find("prnu must be between"), std::string::npos);
}

// A uniform sky seen through dgauss.50mm at f/8 focused far away.
std::string sensorSkyScene(const std::string& camera) {
    return camera + "\nFilm \"image\"\nPixelFilter \"box\"\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\nWorldEnd\n";
}

TEST(CameraSensor, ThroughALensTheCentreCollectsTheProjectedSolidAngleThatPasses) {
    // E / L = integral of cos dw over the directions from the film's centre that pass the lens,
    // found here by tracing a cosine-weighted cone through the exact lens; at L = 1000 cd/m^2 and
    // 1/30 s (the sensor's, not the scene's half-second shutter) the centre reads 0.018 ISO times
    // E t. The f-number alone (pi / (4 N^2), the marginal
    // ray's from infinity) agrees to 0.5%.
    test::TempDir dir;
    const std::string scene = dir.write("sky.pbrt", sensorSkyScene(test::courseCamera("dgauss.50mm.dat",
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
    const double projectedSolidAngle =
        test::passingProjectedSolidAngle(a.lens, {0, 0, a.focus.imageZExact}, {0, 0, 1}, 8 * M_PI / 180, 600);
    const double expected = 0.018 * 100 * 1000 * projectedSolidAngle / 30;
    EXPECT_NEAR(centre, expected, 0.008 * expected);
    EXPECT_NEAR(projectedSolidAngle / (M_PI / (4 * 64)), 1.0, 0.006);
    EXPECT_NE(out.metadata.at("sensor").find("ISO 100, exposure 0.0333333 s"), std::string::npos) << out.metadata.at("sensor");
    // The film's pitch: its 5 mm diagonal over the 50-pixel diagonal.
    EXPECT_NE(out.metadata.at("sensor").find("pitch 100 um"), std::string::npos) << out.metadata.at("sensor");
}

// The sky through dgauss.50mm at f/4 on 40 x 30 pixels.
RenderOutput skyAtF4(const RenderSettings& s, int spp) {
    test::TempDir dir;
    return test::render(dir.write("sky.pbrt", sensorSkyScene(test::courseCamera("dgauss.50mm.dat", "\"float fstop\" 4"))), 40, 30, spp, s);
}

// A sensor of 700 um pixels (35 mm over 50 px), exposed for 1e-4 s (a metered exposure would meter
// the rendered, cropped, part), with more keys.
SensorSpec coarseSensor(const std::string& keys = "") {
    return sensorSpecFromPairs(parseSensorPairs("iso=25600,pitch=700,exposure=0.0001" + keys));
}

TEST(CameraSensor, NoiseBelongsToTheFullFramesPixelsAndAPitchSetsTheFilm) {
    RenderSettings s;
    s.sensor = coarseSensor();
    const RenderOutput full = skyAtF4(s, 2);
    s.crop = std::array<double, 4>{0.5, 1, 0.5, 1};
    const RenderOutput crop = skyAtF4(s, 2);
    ASSERT_EQ(crop.image.width, 20);
    for (int y = 0; y < 15; ++y)
        for (int x = 0; x < 20; ++x)
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_EQ(crop.image.rgb[(std::size_t(y) * 20 + x) * 3 + ch],
                          full.image.rgb[(std::size_t(y + 15) * 40 + x + 20) * 3 + ch]);
    s.crop.reset();
    // The readout runs on the frame's threads, row by row: one thread reads the same frame.
    s.threads = 1;
    EXPECT_EQ(skyAtF4(s, 2).image.rgb, full.image.rgb);
    s.threads = 0;
    s.camera.filmDiagonal = 24;
    EXPECT_THROW(skyAtF4(s, 1), SceneError);
}

TEST(CameraSensor, APinholeHasNoExposureToRead) {
    test::TempDir dir;
    const std::string scene = dir.write("p.pbrt", sensorSkyScene("Camera \"perspective\""));
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

// The Bayer mosaic.

// The filter letter over full-frame site (x, y) of the named pattern, from its name alone.
char filterAt(const std::string& pattern, int x, int y) { return pattern[std::size_t((y % 2) * 2 + x % 2)]; }

int channelOfLetter(char letter) { return letter == 'r' ? 0 : letter == 'g' ? 1 : 2; }

// A frame of the given colour in film values, read through the mosaic with the full frame's origin at (x0, y0).
SensorReadout mosaicOf(SensorSpec s, const std::string& pattern, const SensorCalibration& c, Vec3f colour, int x0, int y0,
                       Image& im, int side = 200) {
    s.colourFilter = bayerPatternNamed(pattern);
    im = flat(side, side, 0);
    for (std::size_t i = 0; i < im.rgb.size(); i += 3) {
        im.rgb[i] = colour.x;
        im.rgb[i + 1] = colour.y;
        im.rgb[i + 2] = colour.z;
    }
    return readOutSensor(s, c, 21, x0, y0, im);
}

TEST(CameraSensorMosaic, PatternsAreNamedAndACropStartsItsOwn) {
    EXPECT_EQ(bayerPatternNamed("rggb")->channels, (std::array<int, 4>{0, 1, 1, 2}));
    EXPECT_EQ(bayerPatternNamed("gbrg")->channels, (std::array<int, 4>{1, 2, 0, 1}));
    EXPECT_FALSE(bayerPatternNamed("rgbg"));
    EXPECT_EQ(bayerPatternNamed("rggb")->from(1, 0).name(), "grbg");
    EXPECT_EQ(bayerPatternNamed("rggb")->from(0, 1).name(), "gbrg");
    EXPECT_EQ(bayerPatternNamed("rggb")->from(3, 5).name(), "bggr");
    EXPECT_EQ(bayerPatternNamed("grbg")->from(2, 4).name(), "grbg");
}

TEST(CameraSensorMosaic, AFlatRedFieldSignalsOnlyAtTheRedSites) {
    SensorSpec s = photonTransferSensor();
    s.readNoiseElectrons = 0;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    const float red = float(5000 / (c.luxSecondsPerValue * c.electronsPerLuxSecond));  // 5,000 e-
    for (const char* pattern : {"rggb", "bggr", "grbg", "gbrg"})
        for (const auto& [x0, y0] : {std::pair{0, 0}, std::pair{3, 6}, std::pair{1, 5}}) {
            Image im;
            const SensorReadout r = mosaicOf(s, pattern, c, {red, 0, 0}, x0, y0, im, 20);
            ASSERT_TRUE(r.mosaic);
            const RawMosaic& raw = *r.mosaic;
            ASSERT_EQ(raw.dn.size(), 400u);
            std::string own;  // the crop's pattern, from the full frame's at its origin
            for (int y = 0; y < 2; ++y)
                for (int x = 0; x < 2; ++x) own += filterAt(pattern, x0 + x, y0 + y);
            EXPECT_EQ(raw.pattern.name(), own) << pattern << " at " << x0 << "," << y0;
            int reds = 0;
            for (int y = 0; y < 20; ++y)
                for (int x = 0; x < 20; ++x) {
                    const double dn = raw.dn[std::size_t(y) * 20 + x];
                    if (filterAt(pattern, x0 + x, y0 + y) == 'r') {
                        ++reds;
                        EXPECT_NEAR(dn, 1024 + 5000 / 2, 5 * std::sqrt(5000.0) / 2) << pattern << " site " << x << "," << y;
                    } else {
                        EXPECT_EQ(dn, 1024) << pattern << " site " << x << "," << y;  // no light, no read or dark noise
                    }
                }
            EXPECT_EQ(reds, 100);
        }
}

TEST(CameraSensorMosaic, DemosaicingKeepsFlatColourEverywhereAndLinearGradientsInside) {
    // Malvar-He-Cutler's kernels weigh each channel to 1 and correct by a Laplacian, zero on a
    // linear field: a flat colour comes back exactly, a linear ramp away from the mirrored edges.
    const int w = 16, h = 12;
    const auto colour = [](int x, int y, int ch) {
        const double base[3] = {0.5, 0.3, 0.2}, dx[3] = {0.01, -0.005, 0.003}, dy[3] = {0.02, 0.01, -0.004};
        return base[ch] + dx[ch] * x + dy[ch] * y;
    };
    for (const char* pattern : {"rggb", "bggr", "grbg", "gbrg"}) {
        std::vector<float> ramp(std::size_t(w) * h), plain(ramp.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int ch = channelOfLetter(filterAt(pattern, x, y));
                ramp[std::size_t(y) * w + x] = float(colour(x, y, ch));
                plain[std::size_t(y) * w + x] = float(colour(0, 0, ch));
            }
        const Image fromRamp = demosaic(ramp, w, h, *bayerPatternNamed(pattern));
        const Image fromPlain = demosaic(plain, w, h, *bayerPatternNamed(pattern));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int ch = 0; ch < 3; ++ch) {
                    const std::size_t i = (std::size_t(y) * w + x) * 3 + ch;
                    ASSERT_NEAR(fromPlain.rgb[i], colour(0, 0, ch), 1e-6) << pattern << " " << x << "," << y << " ch " << ch;
                    if (x >= 2 && x < w - 2 && y >= 2 && y < h - 2) {
                        ASSERT_NEAR(fromRamp.rgb[i], colour(x, y, ch), 1e-5) << pattern << " " << x << "," << y << " ch " << ch;
                    }
                }
    }
    EXPECT_THROW(demosaic(std::vector<float>(5), 1, 5, *bayerPatternNamed("rggb")), std::invalid_argument);
}

TEST(CameraSensorMosaic, AFlatGreyFieldDemosaicsToGreyWithinTheNoise) {
    // 10 / ISO lux s reads 0.18 in every channel: each pixel's three colours within the noise of
    // its sites (1 / sqrt(N) at N electrons a site), their means within 0.3% of 0.18.
    SensorSpec s;
    s.iso = 400;
    s.readNoiseElectrons = 0;
    s.exposureSeconds = 1;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    Image im;
    mosaicOf(s, "rggb", c, Vec3f{1, 1, 1} * float(10 / 400.0), 0, 0, im);
    const double electrons = 10 / 400.0 * c.electronsPerLuxSecond, relative = 1 / std::sqrt(electrons);
    double mean[3] = {0, 0, 0}, chroma = 0;
    const std::size_t n = std::size_t(im.width) * im.height;
    for (std::size_t i = 0; i < n; ++i) {
        for (int ch = 0; ch < 3; ++ch) mean[ch] += im.rgb[i * 3 + ch] / n;
        const double g = im.rgb[i * 3 + 1];
        chroma += (std::pow(im.rgb[i * 3] - g, 2) + std::pow(im.rgb[i * 3 + 2] - g, 2)) / (2 * n);
    }
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean[ch], 0.18, 0.18 * 0.003) << "channel " << ch;
    // A colour difference spans two interpolations of independent sites: under twice a site's noise.
    EXPECT_LT(std::sqrt(chroma) / 0.18, 2 * relative);
    EXPECT_GT(std::sqrt(chroma) / 0.18, 0.5 * relative);  // and the noise is there, not smoothed away
}

TEST(CameraSensorMosaic, EverySiteFollowsThePhotonTransferRelation) {
    // EMVA 1288 per colour: variance = mean / gain + (read / gain)^2 + 1/12 in DN, a site's noise
    // drawn once, through its own filter's channel (red 4,000 e-, green 9,000, blue 1,500).
    const SensorSpec s = photonTransferSensor();
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    const double perValue = c.luxSecondsPerValue * c.electronsPerLuxSecond;
    Image im;
    const SensorReadout r =
        mosaicOf(s, "grbg", c, {float(4000 / perValue), float(9000 / perValue), float(1500 / perValue)}, 0, 0, im);
    const double expectedMean[3] = {2000, 4500, 750};
    double sum[3] = {0, 0, 0}, squares[3] = {0, 0, 0}, count[3] = {0, 0, 0};
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) {
            const int ch = channelOfLetter(filterAt("grbg", x, y));
            const double dn = r.mosaic->dn[std::size_t(y) * 200 + x] - 1024.0;
            sum[ch] += dn;
            squares[ch] += dn * dn;
            ++count[ch];
        }
    for (int ch = 0; ch < 3; ++ch) {
        const double mean = sum[ch] / count[ch], variance = squares[ch] / count[ch] - mean * mean;
        EXPECT_NEAR(mean, expectedMean[ch], 1.0) << "channel " << ch;
        // 10,000 or 20,000 sites: the variance's own scatter is 1.4% or 1%.
        EXPECT_NEAR(variance, mean / 2 + 9 + 1.0 / 12, 0.05 * (mean / 2 + 9)) << "channel " << ch;
    }
    EXPECT_EQ(count[1], 20000);
    EXPECT_EQ(r.wellClipped + r.adcClipped, 0u);
}

TEST(CameraSensorMosaic, WithoutAMosaicTheReadoutIsUnchanged) {
    // The three-photosite readout of a ramp, its whole ADC numbers hashed (FNV-1a): the value main
    // gave before the mosaic was added (64 x 48 pixels from (3, 5) of the full frame, seed 17).
    SensorSpec s;
    s.iso = 3200;
    s.exposureSeconds = 1;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    Image im = flat(64, 48, 0);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            for (int ch = 0; ch < 3; ++ch) im.rgb[(std::size_t(y) * 64 + x) * 3 + ch] = float((x + 2 * y + 40 * ch) * 4e-5);
    Image none = im;
    const SensorReadout r = readOutSensor(s, c, 17, 3, 5, im);
    EXPECT_FALSE(r.mosaic);
    const double perDn = c.gainElectronsPerDn * c.outputPerLuxSecond / c.electronsPerLuxSecond;
    std::uint64_t hash = 1469598103934665603ULL;
    for (float v : im.rgb) hash = (hash ^ std::uint64_t(std::llround(v / perDn + c.blackLevelDn))) * 1099511628211ULL;
    EXPECT_EQ(hash, 14053015699209344921ULL);
    // cfa=none is the same sensor.
    const SensorSpec explicitNone = sensorSpecFromPairs(parseSensorPairs("iso=3200,exposure=1,cfa=none"));
    EXPECT_FALSE(explicitNone.colourFilter);
    readOutSensor(explicitNone, c, 17, 3, 5, none);
    EXPECT_EQ(none.rgb, im.rgb);
}

TEST(CameraSensorMosaic, TheDngFileReadsBackInLibRawWithTheSameNumbers) {
    // A crop from (1, 0) of an rggb sensor starts grbg: LibRaw must see that pattern, the black
    // and white levels, each site's number, and camera colours that are sRGB's (its camera to
    // sRGB matrix, made from ColorMatrix1, the identity).
    SensorSpec s;
    s.iso = 800;
    s.exposureSeconds = 1;
    const SensorCalibration c = calibrateSensor(s, kUnitFilm);
    Image im;
    RenderOutput out;
    out.raw = mosaicOf(s, "rggb", c, Vec3f{0.2f, 0.5f, 0.9f} * float(10 / 800.0), 1, 0, im, 64).mosaic;
    out.image = im;
    ASSERT_TRUE(out.raw);
    test::TempDir dir;
    const std::string path = dir.path() + "/raw.dng";
    writeImageFile(out, path);
    LibRaw libraw;
    ASSERT_EQ(libraw.open_file(path.c_str()), LIBRAW_SUCCESS);
    ASSERT_EQ(libraw.unpack(), LIBRAW_SUCCESS);
    const auto& d = libraw.imgdata;
    EXPECT_NE(d.idata.dng_version, 0u);
    ASSERT_EQ(d.sizes.raw_width, 64);
    ASSERT_EQ(d.sizes.raw_height, 64);
    ASSERT_NE(d.rawdata.raw_image, nullptr);
    const char* letters = "rgbg";  // LibRaw's colours: its second green is 3
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) EXPECT_EQ(letters[libraw.COLOR(y, x)], filterAt("grbg", x, y)) << x << "," << y;
    EXPECT_EQ(d.color.black, 512u);  // 2^(14 - 5)
    EXPECT_EQ(d.color.maximum, 16383u);
    EXPECT_EQ(out.raw->whiteLevelDn, 16383);  // ISO's gain puts the well at or past the ADC's full scale
    SensorSpec coarse = s;
    coarse.gainElectronsPerDn = 10;  // the well's 43,200 e- then read 512 + 4,320 DN
    Image small;
    EXPECT_EQ(mosaicOf(coarse, "rggb", calibrateSensor(coarse, kUnitFilm), {0, 0, 0}, 0, 0, small, 4).mosaic->whiteLevelDn, 4832);
    for (std::size_t i = 0; i < out.raw->dn.size(); ++i) ASSERT_EQ(d.rawdata.raw_image[i], out.raw->dn[i]) << "site " << i;
    EXPECT_EQ(std::string(d.idata.model), "simulated sensor");
    ASSERT_EQ(libraw.dcraw_process(), LIBRAW_SUCCESS);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(d.color.rgb_cam[i][j], i == j ? 1 : 0, 1e-4) << i << "," << j;
}

TEST(CameraSensorMosaic, ARenderKeepsTheFullFramesMosaicAndItsKeysAreChecked) {
    RenderSettings s;
    s.sensor = coarseSensor(",cfa=rggb");
    const RenderOutput full = skyAtF4(s, 2);
    ASSERT_TRUE(full.raw);
    EXPECT_EQ(full.raw->pattern.name(), "rggb");
    EXPECT_NE(full.metadata.at("sensor").find("a rggb Bayer mosaic"), std::string::npos) << full.metadata.at("sensor");
    s.crop = std::array<double, 4>{0.5, 1, 0.5, 1};  // from pixel (20, 15): an odd row starts gbrg
    const RenderOutput crop = skyAtF4(s, 2);
    ASSERT_TRUE(crop.raw);
    EXPECT_EQ(crop.raw->pattern.name(), "gbrg");
    for (int y = 0; y < 15; ++y)
        for (int x = 0; x < 20; ++x) {
            ASSERT_EQ(crop.raw->dn[std::size_t(y) * 20 + x], full.raw->dn[std::size_t(y + 15) * 40 + x + 20]);
            // Two sites from the crop's edges the demosaic sees only the full frame's sites.
            if (x < 2 || x >= 18 || y < 2 || y >= 13) continue;
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_EQ(crop.image.rgb[(std::size_t(y) * 20 + x) * 3 + ch],
                          full.image.rgb[(std::size_t(y + 15) * 40 + x + 20) * 3 + ch]);
        }
    s.crop = std::array<double, 4>{0.5, 0.52, 0, 1};  // one column: nothing to demosaic from
    EXPECT_THROW(skyAtF4(s, 1), SceneError);

    // Without a mosaic a render has no raw numbers, and a DNG is refused by name.
    s.crop.reset();
    s.sensor = coarseSensor();
    const RenderOutput plain = skyAtF4(s, 1);
    EXPECT_FALSE(plain.raw);
    test::TempDir dir;
    try {
        writeImageFile(plain, dir.path() + "/plain.dng");
        ADD_FAILURE() << "a DNG without a mosaic";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("needs a sensor with a colour mosaic"), std::string::npos) << e.what();
    }

    EXPECT_EQ(sensorSpecFromPairs(parseSensorPairs("cfa=bggr")).colourFilter->name(), "bggr");
    EXPECT_NE(sensorKeyError("cfa=rgbg").find("cfa must be one of none, rggb, bggr, grbg, gbrg, got 'rgbg'"), std::string::npos)
        << sensorKeyError("cfa=rgbg");
    EXPECT_NE(sensorKeyError("cfa=1").find("got 1"), std::string::npos) << sensorKeyError("cfa=1");
    EXPECT_NE(sensorKeyError("cfa=rggb,cfa=bggr").find("cfa is given twice"), std::string::npos);
    EXPECT_NE(sensorKeyError("bits=20,cfa=rggb").find("bits must be at most 16 with cfa, got 20"), std::string::npos) << sensorKeyError("bits=20,cfa=rggb");
}

}  // namespace
}  // namespace lenslab
