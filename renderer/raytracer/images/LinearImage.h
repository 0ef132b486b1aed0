#pragma once
// An image file (EXR, HDR, PFM, PNG, TGA, JPEG, ... through OpenImageIO) read as linear RGB for
// lights that an image modulates. Integer-valued files hold sRGB-encoded values and are decoded
// to linear, as pbrt-v3 does for its 8-bit formats; float files are taken as linear.
#include <string>
#include <vector>

#include "core/ParamSet.h"
#include "core/Vec3f.h"

namespace lenslab {

struct LinearImage {
    int width = 0, height = 0;
    std::vector<Vec3f> texels;  // row-major, the file's top row first

    // The texel holding (s, t) in [0, 1]^2: s across, t down from the top row.
    Vec3f lookup(float s, float t) const;
    Vec3f average() const;
};

// Reads `path` (the resolved file for `name`, the name the scene gave). SceneError at `where`
// naming the file when it cannot be read or holds no pixels.
LinearImage readLinearImage(const std::string& path, const std::string& name, const SourceLocation& where);

}  // namespace lenslab
