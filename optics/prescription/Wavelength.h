#pragma once
// The wavelengths lenslab traces, and the one check of a wavelength every entry point makes: a
// lens file's primary and listed wavelengths (.zmx WAVM/PWAV, .seq WL, the editor's JSON), a
// --wavelength or ?wavelength= setting, an analysis's list.
#include <optional>
#include <string>

#include "prescription/NumberText.h"

namespace lenslab {

// nm: the range glass data cover, from fused silica's and calcium fluoride's formulas in the deep
// ultraviolet (an excimer lithography lens at 193 or 248 nm) to the makers' catalogs' 2.5 um (a
// telecom collimator at 1550 nm). Thermal infrared needs materials no bundled catalog has. Where a
// wavelength lies outside one glass's own data the lens still reads, with a warning (RowMedium.h).
constexpr double kShortestWavelength = 180.0;
constexpr double kLongestWavelength = 2500.0;

// nm: the visible range of the CIE observer, which colour covers (spectral renders, whole nm) and
// which a model glass's nd and Vd describe.
constexpr int kVisibleFirstNm = 360, kVisibleLastNm = 830;

// Why `nm` cannot be traced ("wavelength 100 nm lies outside 180-2500 nm"), or nullopt when it can.
inline std::optional<std::string> wavelengthProblem(double nm) {
    if (nm >= kShortestWavelength && nm <= kLongestWavelength) return std::nullopt;
    return "wavelength " + formatNumber(nm) + " nm lies outside " + formatNumber(kShortestWavelength) + "-" +
           formatNumber(kLongestWavelength) + " nm";
}

}  // namespace lenslab
