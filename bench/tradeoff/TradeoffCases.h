#pragma once
// What the speed-against-accuracy study measures: the four bundled lenses at their widest stop,
// f/5.6 and f/11, focused at 5.5 m, on a 36 x 24 mm film, at three field positions.
#include <optional>
#include <string>
#include <vector>

namespace lenslab::tradeoff {

constexpr double kFilmWidthMm = 36, kFilmHeightMm = 24;
constexpr double kFocusDistanceMm = 5500;
constexpr int kFrameWidth = 240, kFrameHeight = 160;  // the "small frame" of the frame timings

struct LensCase {
    std::string name;   // bundled lens table, without .dat
    std::string path;
};

struct StopCase {
    std::optional<double> fstop;  // nullopt: the widest
    std::string label;            // "widest", "f/5.6", "f/11"
};

struct FieldCase {
    double fraction;    // of the film's half diagonal, along the diagonal
    std::string label;  // "centre", "half", "corner"
};

std::vector<LensCase> lensCases();
std::vector<StopCase> stopCases();
std::vector<FieldCase> fieldCases();
double filmDiagonalMm();
double filmHalfDiagonalMm();

}  // namespace lenslab::tradeoff
