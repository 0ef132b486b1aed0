#pragma once
// Image files of any format (EXR, HDR, PFM, PNG, TGA, JPEG, TIFF, ...; ImageFileReader) as the RGB
// numbers they store: integer formats scaled to [0, 1] and still encoded, float formats as is.
#include <string>
#include <vector>

#include "core/ParamSet.h"
#include "core/Vec3f.h"

namespace lenslab {

struct RgbImageFile {
    int width = 0, height = 0;
    std::vector<Vec3f> rgb;      // row-major, the file's top row first; grey files in all channels
    bool integerFormat = false;  // 8 or 16 bits per channel: sRGB-encoded by pbrt-v3's convention
    bool eightBit = false;       // values are exact multiples of 1/255
};

// The sRGB transfer function undone: encoded value in [0, 1] to linear.
float srgbDecode(float encoded);

// Reads `path` (the resolved file for `name`, as the scene gave it). A SceneError at `where`
// naming the file when it cannot be read or holds no pixels.
RgbImageFile readRgbImageFile(const std::string& path, const std::string& name, const SourceLocation& where);

}  // namespace lenslab
