#pragma once
// The wavelengths lenslab traces, and the one check of a wavelength every entry point makes: a
// lens file's primary and listed wavelengths (.zmx WAVM/PWAV, the editor's JSON), a --wavelength
// or ?wavelength= setting, an analysis's list. Glass data and the CIE observer cover this range.
#include <optional>
#include <string>

#include "prescription/NumberText.h"

namespace lenslab {

// nm: the visible range of the CIE observer.
constexpr double kShortestWavelength = 360.0;
constexpr double kLongestWavelength = 830.0;

// Why `nm` cannot be traced ("wavelength 100 nm lies outside 360-830 nm"), or nullopt when it can.
inline std::optional<std::string> wavelengthProblem(double nm) {
    if (nm >= kShortestWavelength && nm <= kLongestWavelength) return std::nullopt;
    return "wavelength " + formatNumber(nm) + " nm lies outside " + formatNumber(kShortestWavelength) + "-" +
           formatNumber(kLongestWavelength) + " nm";
}

}  // namespace lenslab
