#pragma once
// A pixel's estimate as the film stores it: the exposure scale, then pbrt-v4's sensor: the CIE
// 1931 observer, white balanced when asked (film/WhiteBalance.h), or a measured camera
// (film/MeasuredCameraSensor.h, white balanced by its own fit).
#include <optional>

#include "core/Vec3f.h"
#include "film/MeasuredCameraSensor.h"
#include "film/WhiteBalance.h"
#include "scene/SceneDescription.h"

namespace lenslab {

class FilmColour {
public:
    explicit FilmColour(const FilmSpec& film);
    Vec3f operator()(Vec3f v) const;

private:
    float scale_;
    std::optional<Rgb3x3> whiteBalance_;
    std::optional<MeasuredCameraSensor> camera_;
};

}  // namespace lenslab
