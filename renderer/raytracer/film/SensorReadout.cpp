#include "film/SensorReadout.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <sstream>

#include "film/Demosaic.h"
#include "prescription/NumberText.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {

// Photons per square metre in one lux second of 555 nm light (683 lm/W there): lambda / (h c 683).
constexpr double kPhotonsPerLuxSecondM2 = 555e-9 / (6.62607015e-34 * 299792458.0 * 683.0);
constexpr double kWellElectronsPerUm2 = 2700;  // Nikon D850: about 51,000 e- in 4.35 um pixels
constexpr double kStandardOutputExposure = 10;  // lux s x ISO that reads 0.18 (ISO 12232 SOS)
constexpr double kSaturationExposure = 78;      // lux s x ISO at the ADC's full scale (ISO 12232 S_sat)

// Pcg32 as the standard library's distributions take it (a uniform random bit generator).
struct PcgBits {
    using result_type = std::uint32_t;
    Pcg32 pcg;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return 0xffffffffu; }
    result_type operator()() { return pcg.next(); }
};

std::uint64_t siteKey(std::uint64_t seed, int x, int y, int channel) {
    return hashCombine(hashCombine(seed, (std::uint64_t(std::uint32_t(y)) << 32) | std::uint32_t(x)), std::uint64_t(channel));
}

double normal(PcgBits& bits, double sigma) {
    return sigma > 0 ? std::normal_distribution<double>(0.0, sigma)(bits) : 0.0;
}

// The electrons a photosite of capacity fullWell collects from a Poisson mean, clipped to the well.
// A mean so far past the well that a draw falls below it less often than once in 1e15 is full
// without drawing: the standard library's Poisson sampler rejects every sample once its mean nears
// 2^63 (a bright sky at a long exposure), and the render hung there. Below that the mean is at most
// the well (1e12 at most) plus a few deviations, where the sampler is exact and quick.
double collectedElectrons(double mean, double fullWell, PcgBits& noise) {
    constexpr double kSaturatedDeviations = 8;
    if (!(mean > 0)) return 0;
    if (!(mean - kSaturatedDeviations * std::sqrt(mean) < fullWell)) return fullWell;  // an infinite mean too
    return std::min(fullWell, double(std::poisson_distribution<long long>(mean)(noise)));
}


}  // namespace

std::string sensorWithoutLens(const std::string& cameraType) {
    return "the sensor needs a lens to expose through (Camera \"realistic\"); this scene's camera is \"" + cameraType + "\"";
}

std::optional<double> sensorFilmDiagonalMm(const SensorSpec& spec, std::optional<double> askedMm, int width, int height) {
    if (!spec.pitchMicrometres) return std::nullopt;
    const double diagonal = *spec.pitchMicrometres * 1e-3 * std::hypot(double(width), double(height));
    if (askedMm && std::fabs(*askedMm - diagonal) > 1e-6 * diagonal)
        throw SceneError("sensor: pitch " + formatNumber(*spec.pitchMicrometres) + " um over " + std::to_string(width) + "x" +
                              std::to_string(height) + " pixels makes a film diagonal of " + formatNumber(diagonal) + " mm, not the " +
                              formatNumber(*askedMm) + " mm asked for");
    return diagonal;
}

SensorCalibration calibrateSensor(const SensorSpec& spec, const SensorExposureInput& input) {
    if (!(input.exposurePerValue > 0) || !std::isfinite(input.exposurePerValue))
        throw SensorSpecError("sensor: the film has no exposure to read (its camera has no lens)");
    SensorCalibration c;
    c.pitchMicrometres = input.filmPitchMicrometres;
    if (spec.pitchMicrometres && std::fabs(*spec.pitchMicrometres - c.pitchMicrometres) > 1e-6 * c.pitchMicrometres)
        throw SensorSpecError("sensor: pitch " + formatNumber(*spec.pitchMicrometres) + " um disagrees with the film's " +
                              formatNumber(c.pitchMicrometres) + " um (its diagonal over the pixel diagonal)");
    const double areaM2 = c.pitchMicrometres * c.pitchMicrometres * 1e-12;
    c.fullWellElectrons = spec.fullWellElectrons.value_or(kWellElectronsPerUm2 * c.pitchMicrometres * c.pitchMicrometres);
    c.electronsPerLuxSecond = spec.quantumEfficiency * spec.fillFactor * areaM2 * kPhotonsPerLuxSecondM2;
    const double luxSecondsPerValueAtCamera = spec.nits * input.exposurePerValue;
    // Metered: the time at which the frame's mean luminance reads the standard output's 0.18.
    const double metered = input.meanLuminance > 0
                               ? input.cameraSeconds * kStandardOutputExposure / (spec.iso * input.meanLuminance * luxSecondsPerValueAtCamera)
                               : input.cameraSeconds;
    c.exposureSeconds = spec.exposureSeconds.value_or(metered);
    c.luxSecondsPerValue = luxSecondsPerValueAtCamera * c.exposureSeconds / input.cameraSeconds;
    c.fullScaleDn = std::ldexp(1.0, spec.adcBits) - 1;
    c.blackLevelDn = spec.blackLevelDn.value_or(std::ldexp(1.0, std::max(0, spec.adcBits - 5)));
    const double saturationElectrons = std::min(c.fullWellElectrons, kSaturationExposure / spec.iso * c.electronsPerLuxSecond);
    c.gainElectronsPerDn = spec.gainElectronsPerDn.value_or(saturationElectrons / (c.fullScaleDn - c.blackLevelDn));
    c.baseIso = kSaturationExposure * c.electronsPerLuxSecond / c.fullWellElectrons;
    c.outputPerLuxSecond = 0.18 * spec.iso / kStandardOutputExposure;
    return c;
}

SensorReadout readOutSensor(const SensorSpec& spec, const SensorCalibration& c, std::uint64_t seed, int x0, int y0,
                            Image& image) {
    SensorReadout readout;
    const double electronsPerValue = c.luxSecondsPerValue * c.electronsPerLuxSecond;
    const double outputPerElectron = c.outputPerLuxSecond / c.electronsPerLuxSecond;
    const double readDn = spec.readNoiseElectrons / c.gainElectronsPerDn;
    const std::uint64_t noiseSeed = hashCombine(seed, 0x5e45041e7ea1ULL);  // apart from the renderer's own uses of the seed
    // Counted from every row's thread; clipping is rare, so the counters are not contended.
    std::atomic<std::uint64_t> wellClipped{0}, adcClipped{0};
    // The ADC number of the photosite of channel ch at full-frame pixel (x, y), exposed to a film value.
    const auto readSite = [&](double value, int x, int y, int ch) {
        PcgBits pattern{Pcg32(siteKey(spec.patternSeed, x, y, ch))};
        const double response = 1 + normal(pattern, spec.prnu);
        const double darkRate = std::max(0.0, spec.darkCurrentElectronsPerSecond + normal(pattern, spec.dsnuElectronsPerSecond));
        const double mean = std::max(0.0, value * electronsPerValue * response) + darkRate * c.exposureSeconds;
        PcgBits noise{Pcg32(siteKey(noiseSeed, x, y, ch))};
        const double electrons = collectedElectrons(mean, c.fullWellElectrons, noise);
        if (electrons >= c.fullWellElectrons) wellClipped.fetch_add(1, std::memory_order_relaxed);
        const double dn = std::nearbyint(electrons / c.gainElectronsPerDn + c.blackLevelDn + normal(noise, readDn));
        if (dn >= c.fullScaleDn) adcClipped.fetch_add(1, std::memory_order_relaxed);
        return std::clamp(dn, 0.0, c.fullScaleDn);
    };
    const auto developed = [&](double dn) { return float((dn - c.blackLevelDn) * c.gainElectronsPerDn * outputPerElectron); };
    // Rows in parallel: every site's numbers come from its own key, so the image is the same for
    // any thread count.
    const auto eachRow = [&](const auto& readRow) {
        tbb::parallel_for(tbb::blocked_range<int>(0, image.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y != rows.end(); ++y) readRow(y);
        });
        readout.wellClipped = wellClipped.load();
        readout.adcClipped = adcClipped.load();
    };
    if (!spec.colourFilter) {
        eachRow([&](int y) {
            for (int x = 0; x < image.width; ++x)
                for (int ch = 0; ch < 3; ++ch) {
                    float& value = image.rgb[(std::size_t(y) * image.width + x) * 3 + ch];
                    value = developed(readSite(value, x0 + x, y0 + y, ch));
                }
        });
        return readout;
    }
    // One photosite a pixel, behind its filter: its channel's value alone is read, then demosaiced.
    RawMosaic& raw = readout.mosaic.emplace();
    raw.width = image.width;
    raw.height = image.height;
    raw.pattern = spec.colourFilter->from(x0, y0);
    raw.blackLevelDn = c.blackLevelDn;
    raw.whiteLevelDn = std::min(c.fullScaleDn, std::nearbyint(c.blackLevelDn + c.fullWellElectrons / c.gainElectronsPerDn));
    raw.dn.resize(std::size_t(image.width) * image.height);
    std::vector<float> sites(raw.dn.size());
    eachRow([&](int y) {
        for (int x = 0; x < image.width; ++x) {
            const std::size_t i = std::size_t(y) * image.width + x;
            const int ch = raw.pattern.channelAt(x, y);
            const double dn = readSite(image.rgb[i * 3 + ch], x0 + x, y0 + y, ch);
            raw.dn[i] = std::uint16_t(dn);
            sites[i] = developed(dn);
        }
    });
    image = demosaic(sites, image.width, image.height, raw.pattern);
    return readout;
}

std::map<std::string, std::string> describeSensor(const SensorSpec& spec, const SensorCalibration& c,
                                                  const SensorReadout& readout) {
    std::ostringstream s;
    s << "ISO " << formatNumber(spec.iso) << (spec.exposureSeconds ? ", exposure " : ", metered exposure ") << formatNumber(c.exposureSeconds)
      << " s, pitch " << formatNumber(c.pitchMicrometres) << " um, fill " << formatNumber(spec.fillFactor) << ", QE " << formatNumber(spec.quantumEfficiency)
      << ", full well " << formatNumber(c.fullWellElectrons) << " e-, gain " << formatNumber(c.gainElectronsPerDn) << " e-/DN, "
      << spec.adcBits << "-bit ADC, black " << formatNumber(c.blackLevelDn) << " DN, read noise " << formatNumber(spec.readNoiseElectrons)
      << " e-, dark current " << formatNumber(spec.darkCurrentElectronsPerSecond) << " e-/s (DSNU " << formatNumber(spec.dsnuElectronsPerSecond)
      << "), PRNU " << formatNumber(spec.prnu) << ", base ISO " << formatNumber(c.baseIso) << ", " << formatNumber(spec.nits)
      << " cd/m^2 per unit radiance; developed by standard output sensitivity (0.18 at 10 / ISO lux s)"
      << (spec.colourFilter ? "; a " + spec.colourFilter->name() + " Bayer mosaic, demosaiced by Malvar-He-Cutler" : "");
    return {{"sensor", s.str()},
            {"sensorElectronsPerValue", formatNumber(c.luxSecondsPerValue * c.electronsPerLuxSecond)},
            {"sensorClipped", std::to_string(readout.wellClipped) + " photosites at the full well, " +
                                  std::to_string(readout.adcClipped) + " at the ADC's full scale"}};
}

}  // namespace lenslab
