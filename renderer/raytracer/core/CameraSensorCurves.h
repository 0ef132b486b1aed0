#pragma once
// The measured spectral sensitivities of the cameras that pbrt-v4's Film "string sensor" names
// ("nikon_d850", "canon_eos_5d_mkiv", ...): per camera its red, green and blue pixels' relative
// response against wavelength. film/MeasuredCameraSensor.h turns them into the film's colours.
#include <string>

#include "core/TabulatedSpectrum.h"

namespace lenslab {

struct CameraSensorCurves {
    const char* name;
    TabulatedSpectrum r, g, b;
};

// The camera of that name, or null.
const CameraSensorCurves* findCameraSensorCurves(const std::string& name);
// Every name, comma separated, for an error message.
std::string cameraSensorNames();

}  // namespace lenslab
