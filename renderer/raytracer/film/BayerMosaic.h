#pragma once
// A Bayer colour filter mosaic (docs/sensor.md): each photosite behind one filter, red, green or
// blue, in a 2 x 2 cell repeated over the sensor; and the raw numbers such a sensor reads out.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct BayerPattern {
    // The channel (0 red, 1 green, 2 blue) of the cell's sites, row by row: (0, 0), (1, 0), (0, 1), (1, 1).
    std::array<int, 4> channels{};

    int channelAt(int x, int y) const { return channels[std::size_t((y & 1) * 2 + (x & 1))]; }
    // The pattern as it starts at site (x0, y0): a crop's own pattern.
    BayerPattern from(int x0, int y0) const;
    std::string name() const;  // "rggb"
};

constexpr std::array<const char*, 4> kBayerPatternNames = {"rggb", "bggr", "grbg", "gbrg"};

// One of kBayerPatternNames; nothing for another name.
std::optional<BayerPattern> bayerPatternNamed(const std::string& name);

// The ADC numbers of a mosaic sensor, black level included, one site a pixel, row-major, top row
// first. Its pattern is the one at its own first site.
struct RawMosaic {
    int width = 0, height = 0;
    BayerPattern pattern;
    std::vector<std::uint16_t> dn;
    double blackLevelDn = 0, whiteLevelDn = 0;
    std::string description;  // the sensor's calibration, for the raw file
};

}  // namespace lenslab
