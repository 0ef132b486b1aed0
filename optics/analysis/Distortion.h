#pragma once
// Distortion against field angle, by exact tracing of chief rays (object at infinity).
//
// The chief ray of a field angle theta is the ray from the scene at that angle that passes through
// the centre of the aperture stop. Its height on the paraxial focal plane (z = F') is the real
// image height; the paraxial (distortion-free, rectilinear) height is f tan(theta). Distortion is
// 100 (real - paraxial) / paraxial percent: negative is barrel, positive pincushion.
//
// Millimetres and degrees; lens space (origin at the front vertex, +z toward the scene).
#include <optional>
#include <vector>

#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "trace/Vec3.h"

namespace lenslab {

struct DistortionSample {
    double fieldDegrees = 0;      // angle of the incoming chief ray to the axis
    double imageHeight = 0;       // real chief-ray height on the F' plane, mm (positive: the usual inverted image)
    double paraxialHeight = 0;    // f tan(theta), mm
    double distortionPercent = 0;
    bool found = false;           // a chief ray through the stop centre exists and leaves the lens
};

// Samples at `count` equally spaced field angles from 0 to maxFieldDegrees (< 90). At 0 the
// distortion is its limit, 0.
std::vector<DistortionSample> distortionCurve(const LensSystem& lens, const FirstOrder& fo, double maxFieldDegrees,
                                              int count);

}  // namespace lenslab
