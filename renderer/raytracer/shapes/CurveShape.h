#pragma once
// pbrt-v3's "curve": cubic (or quadratic, raised to cubic) Bezier or B-spline segments with a width
// varying linearly from width0 to width1 along the whole curve, as Embree's curve primitives:
// "flat" (a ribbon facing the ray), "cylinder" (a round tube) or "ribbon" (oriented by "N").
#include <memory>

#include "shapes/Shape.h"

namespace lenslab {

// Throws SceneError naming the parameter for bad input.
std::shared_ptr<const Shape> makeCurve(const ParamSet& params, const Transform& objectToGroup);

}  // namespace lenslab
