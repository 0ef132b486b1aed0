#include "film/SensorSpec.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>

#include "prescription/NumberText.h"

namespace lenslab {

namespace {

struct SensorKey {
    const char* name;
    double min, max;
    bool whole;  // a whole number
    std::function<void(SensorSpec&, double)> set;
};

// Enough digits that a refused value reads as given (bits 16.0000001, not 16).
std::string shown(double v) { return formatNumber(v, 12); }

const std::vector<SensorKey>& sensorKeys() {
    static const std::vector<SensorKey> keys = {
        {"iso", 1, 1e7, false, [](SensorSpec& s, double v) { s.iso = v; }},
        {"exposure", 1e-9, 1e5, false, [](SensorSpec& s, double v) { s.exposureSeconds = v; }},
        {"gain", 1e-6, 1e9, false, [](SensorSpec& s, double v) { s.gainElectronsPerDn = v; }},
        {"qe", 1e-6, 1, false, [](SensorSpec& s, double v) { s.quantumEfficiency = v; }},
        {"fill", 1e-6, 1, false, [](SensorSpec& s, double v) { s.fillFactor = v; }},
        {"pitch", 0.1, 1000, false, [](SensorSpec& s, double v) { s.pitchMicrometres = v; }},
        {"fullwell", 1, 1e12, false, [](SensorSpec& s, double v) { s.fullWellElectrons = v; }},
        {"read", 0, 1e6, false, [](SensorSpec& s, double v) { s.readNoiseElectrons = v; }},
        {"dark", 0, 1e9, false, [](SensorSpec& s, double v) { s.darkCurrentElectronsPerSecond = v; }},
        {"dsnu", 0, 1e9, false, [](SensorSpec& s, double v) { s.dsnuElectronsPerSecond = v; }},
        {"prnu", 0, 0.5, false, [](SensorSpec& s, double v) { s.prnu = v; }},
        {"bits", 1, 24, true, [](SensorSpec& s, double v) { s.adcBits = int(v); }},
        {"black", 0, 1 << 24, true, [](SensorSpec& s, double v) { s.blackLevelDn = v; }},
        {"nits", 1e-12, 1e12, false, [](SensorSpec& s, double v) { s.nits = v; }},
        {"pattern", 0, 9007199254740992.0, true, [](SensorSpec& s, double v) { s.patternSeed = std::uint64_t(v); }},
    };
    return keys;
}

constexpr const char* kColourFilterKey = "cfa";
constexpr int kRawBits = 16;  // a mosaic's raw numbers are 16-bit samples (RawMosaic, its DNG file)

std::string keyList() {
    std::string list;
    for (const SensorKey& k : sensorKeys()) list += std::string(k.name) + " ";
    return list + kColourFilterKey;
}

// cfa: none (three photosites a pixel) or a Bayer pattern's name.
void setColourFilter(SensorSpec& spec, const SensorValue& value) {
    const std::string* word = std::get_if<std::string>(&value);
    if (word && *word == "none") {
        spec.colourFilter.reset();
        return;
    }
    spec.colourFilter = word ? bayerPatternNamed(*word) : std::nullopt;
    if (!spec.colourFilter) {
        std::string names = "none";
        for (const char* name : kBayerPatternNames) names += std::string(", ") + name;
        throw SensorSpecError(std::string("sensor: ") + kColourFilterKey + " must be one of " + names + ", got " +
                              (word ? "'" + word->substr(0, 40) + "'" : shown(std::get<double>(value))));
    }
}

}  // namespace

SensorSpec sensorSpecFromPairs(const SensorPairs& pairs) {
    SensorSpec spec;
    std::vector<std::string> seen;
    for (const auto& [name, value] : pairs) {
        const SensorKey* key = nullptr;
        for (const SensorKey& k : sensorKeys())
            if (name == k.name) key = &k;
        if (!key && name != kColourFilterKey)
            throw SensorSpecError("sensor: unknown key '" + name.substr(0, 40) + "' (keys: " + keyList() + ")");
        for (const std::string& s : seen)
            if (s == name) throw SensorSpecError("sensor: " + name + " is given twice");
        seen.push_back(name);
        if (!key) {
            setColourFilter(spec, value);
            continue;
        }
        const double* number = std::get_if<double>(&value);
        if (!number)
            throw SensorSpecError("sensor: " + name + "'s value '" + std::get<std::string>(value).substr(0, 40) + "' is not a number");
        const double v = *number;
        if (!std::isfinite(v) || v < key->min || v > key->max || (key->whole && v != std::floor(v)))
            throw SensorSpecError("sensor: " + name + " must be " + (key->whole ? "a whole number " : "") + "between " +
                                  shown(key->min) + " and " + shown(key->max) + ", got " + shown(v));
        key->set(spec, v);
    }
    const double fullScale = std::ldexp(1.0, spec.adcBits) - 1;
    if (spec.blackLevelDn && *spec.blackLevelDn >= fullScale)
        throw SensorSpecError("sensor: black " + shown(*spec.blackLevelDn) + " DN must lie below the " +
                              std::to_string(spec.adcBits) + "-bit full scale " + shown(fullScale));
    if (spec.colourFilter && spec.adcBits > kRawBits)
        throw SensorSpecError("sensor: a colour mosaic's raw numbers are " + std::to_string(kRawBits) + "-bit: bits must be at most " +
                              std::to_string(kRawBits) + " with cfa, got " + std::to_string(spec.adcBits));
    return spec;
}

SensorPairs parseSensorPairs(const std::string& text) {
    SensorPairs pairs;
    std::stringstream items(text);
    for (std::string item; std::getline(items, item, ',');) {
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw SensorSpecError("sensor: '" + item.substr(0, 40) + "' is not key=value (as in iso=800,exposure=0.01)");
        const std::string value = item.substr(eq + 1);
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (!value.empty() && end == value.c_str() + value.size()) pairs.emplace_back(item.substr(0, eq), v);
        else pairs.emplace_back(item.substr(0, eq), value);
    }
    return pairs;
}

}  // namespace lenslab
