#pragma once

namespace lenslab {

// Pi, for the angles lens files and settings state in degrees and the pupil's polar coordinates.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace lenslab
