#pragma once

namespace lenslab {

// Pi and its inverse in the renderer's single precision (optics/prescription/Pi.h holds the double).
inline constexpr float kPif = 3.14159265f;
inline constexpr float kInvPif = 0.318309886f;

}  // namespace lenslab
