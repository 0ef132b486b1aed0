#pragma once
// A real camera sensor behind the film (docs/sensor.md): what its photosites collect, how they are
// read out and with what noise. Off by default; the noiseless film stays the picture renders are
// compared by. Given as key=value pairs (the command line's --sensor, the API's "sensor" object),
// each checked against its range here, once for both.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "film/BayerMosaic.h"

namespace lenslab {

struct SensorSpec {
    double iso = 100;                  // ISO 12232 standard output sensitivity: the output's gain
    std::optional<double> exposureSeconds;  // unset: metered (the frame's mean luminance at 0.18)
    std::optional<double> gainElectronsPerDn;  // unset: ISO's (full scale at the saturation exposure 78 / ISO lux s)
    double quantumEfficiency = 0.5;    // electrons per photon at 555 nm
    double fillFactor = 1;             // the photosite's light-collecting share of its pixel
    std::optional<double> pitchMicrometres;  // unset: the film's (diagonal over the pixel diagonal)
    std::optional<double> fullWellElectrons; // unset: 2,700 e- per square micrometre (Nikon D850's density)
    double readNoiseElectrons = 2.5;   // rms, per read
    double darkCurrentElectronsPerSecond = 0.1;
    double dsnuElectronsPerSecond = 0.05;  // rms over pixels of the dark current (a fixed pattern)
    double prnu = 0.005;               // rms over pixels of the response, as a fraction (a fixed pattern)
    int adcBits = 14;
    std::optional<double> blackLevelDn;   // unset: 2^(bits - 5), room below black for the read noise
    double nits = 1;                   // cd/m^2 of a scene radiance whose luminance is 1
    std::uint64_t patternSeed = 0;     // the fixed pattern's: the same sensor in every frame
    // unset: three photosites a pixel; set: one a pixel behind this Bayer filter pattern (at the
    // full frame's first pixel), demosaiced into the picture, its raw numbers kept (film/BayerMosaic.h).
    std::optional<BayerPattern> colourFilter;
};

// A key's value: a number, or a word (cfa's).
using SensorValue = std::variant<double, std::string>;
using SensorPairs = std::vector<std::pair<std::string, SensorValue>>;

class SensorSpecError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// From key=value pairs (keys: iso exposure gain qe fill pitch fullwell read dark dsnu prnu bits
// black nits pattern, numbers; cfa, none or a Bayer pattern); throws SensorSpecError naming the
// key, its range and the value.
SensorSpec sensorSpecFromPairs(const SensorPairs& pairs);

// "iso=800,exposure=0.01,cfa=rggb" as the command line gives it: numbers where they read as one.
SensorPairs parseSensorPairs(const std::string& text);

}  // namespace lenslab
