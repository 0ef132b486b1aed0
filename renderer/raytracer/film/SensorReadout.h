#pragma once
// The sensor of SensorSpec exposed to a rendered frame and read out (docs/sensor.md). The film's
// values become focal-plane exposure in lux seconds through the lens camera's radiometry
// (Camera::filmExposurePerValue) and the scene's luminance unit; each pixel's channels then
// collect photo-electrons (Poisson, with the fixed-pattern response PRNU), dark current (Poisson,
// with its fixed pattern DSNU), fill to at most the full well, and are read with Gaussian read
// noise through the gain into whole ADC numbers above the black level, clipped to the ADC's range.
// Each pixel's three channels are three photosites, or, behind a Bayer colour filter mosaic
// (SensorSpec::colourFilter), one photosite a pixel reads its filter's channel and the picture is
// demosaiced from them (film/Demosaic.h).
//
// The output is the developed picture by ISO 12232's standard output sensitivity: a focal-plane
// exposure of 10 / ISO lux s reads 0.18 (linear), so an ISO twice as high at half the exposure
// gives the same brightness with the noise of half the light. ISO also sets the gain, unless one is
// given: the ADC's full scale at the saturation exposure 78 / ISO lux s, or at the full well where
// that is reached first (below the base ISO, 78 / the full well's exposure).
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "film/SensorSpec.h"
#include "Render.h"

namespace lenslab {

// What the frame knows that the sensor needs.
struct SensorExposureInput {
    double exposurePerValue = 0;  // focal-plane radiant exposure (radiance x sr x s) per film value
    double cameraSeconds = 1;     // the exposure time exposurePerValue includes (the shutter's)
    double filmPitchMicrometres = 0;
    double meanLuminance = 0;     // of the noiseless frame's values, for the metered exposure
};

struct SensorCalibration {
    double pitchMicrometres = 0, fullWellElectrons = 0;
    double exposureSeconds = 0;
    double electronsPerLuxSecond = 0;  // a photosite's, at 555 nm
    double luxSecondsPerValue = 0;     // the focal-plane exposure a film value of 1 gives
    double gainElectronsPerDn = 0, blackLevelDn = 0, fullScaleDn = 0;
    double baseIso = 0;                // where the saturation exposure just fills the well
    double outputPerLuxSecond = 0;     // 0.18 at 10 / ISO lux s
};

// The refusal of a sensor behind a camera of this type, which has no lens.
std::string sensorWithoutLens(const std::string& cameraType);

// The film diagonal (mm) a sensor's pitch makes over width x height pixels; nullopt when it gives
// none. Throws SceneError when a diagonal asked for as well disagrees.
std::optional<double> sensorFilmDiagonalMm(const SensorSpec& spec, std::optional<double> askedMm, int width, int height);

// Throws SensorSpecError when the frame cannot be exposed (no lens radiometry, a pitch unlike the film's).
SensorCalibration calibrateSensor(const SensorSpec& spec, const SensorExposureInput& input);

struct SensorReadout {
    std::uint64_t wellClipped = 0, adcClipped = 0;  // photosites that filled the well, reached full scale
    std::optional<RawMosaic> mosaic;                // a colour mosaic's ADC numbers
};

// Replaces the image's values by the sensor's developed readout. Pixel (x, y) of the image is
// (x0 + x, y0 + y) of the full frame: the fixed pattern and the colour filter belong to the full
// frame, and the noise to (seed, full-frame pixel, channel), so crops and tile spreads give the
// same pixels.
SensorReadout readOutSensor(const SensorSpec& spec, const SensorCalibration& calibration, std::uint64_t seed, int x0,
                            int y0, Image& image);

// The calibration and its inputs for the image's metadata.
std::map<std::string, std::string> describeSensor(const SensorSpec& spec, const SensorCalibration& calibration,
                                                  const SensorReadout& readout);

}  // namespace lenslab
