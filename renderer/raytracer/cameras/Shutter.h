#pragma once
// The camera's shutter: open from shutteropen to shutterclose in scene time (pbrt's defaults 0 and
// 1). Each camera ray is taken at its own moment in that interval, drawn from the pixel sampler's
// time dimension; the moment decides where moving shapes, instances and the camera stand for every
// ray of its path. The interval places the exposure in time: its length weights the picture only
// where a camera simulates exposure (the realistic camera), as in pbrt.
#include "core/AnimatedTransform.h"
#include "core/ParamSet.h"

namespace lenslab {

struct Shutter {
    double open = 0, close = 1;

    // The moment of time sample u in [0, 1), as the fraction through the transform times that rays carry.
    float moment(float u, const TransformTimes& times) const { return times.fraction(open + double(u) * (close - open)); }
};

// The Camera directive's shutteropen and shutterclose; SceneError naming them when close precedes open.
Shutter readShutter(const ParamSet& cameraParams);

}  // namespace lenslab
