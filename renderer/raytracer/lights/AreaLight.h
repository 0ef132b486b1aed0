#pragma once
// pbrt-v3's "diffuse" area light: radiance L leaving one primitive of a shape (a triangle, or a
// whole quadric) on the side its oriented normal points to, or on both sides. Points on it are
// drawn by the shape's area sampling; the pdf turns into solid angle at the shading point.
#include <memory>

#include "lights/Light.h"
#include "shapes/Shape.h"

namespace lenslab {

// The shape must lie in world space (area lights inside instanced objects are not supported).
std::unique_ptr<Light> makeDiffuseAreaLight(std::shared_ptr<const Shape> shape, std::size_t primitive, Vec3f L,
                                            bool twoSided);

}  // namespace lenslab
