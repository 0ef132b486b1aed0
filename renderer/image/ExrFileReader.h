#pragma once
// OpenEXR files read by OpenEXR itself, which lenslab links for its own EXR output anyway: loading
// the OpenImageIO plugin costs a process 0.28 s of CPU (its 250 libraries), a tenth of a small
// frame lit by an EXR sky.
#include <optional>
#include <string>

#include "ImageFileReader.h"

namespace lenslab {

// Whether the file begins with OpenEXR's magic number.
bool isExrFile(const std::string& path);

// The data window's R, G, B (and A), or Y (and A), channels of half or float type as floats, in
// that order, top row first. Nothing when the file holds other channels or types (the caller then
// asks OpenImageIO); throws std::runtime_error with OpenEXR's reason when it cannot be read.
std::optional<DecodedImage> readExrFile(const std::string& path);

}  // namespace lenslab
