#pragma once
// Lights whose emission an image shapes, each in the light's own space (the current transform at
// LightSource): pbrt-v3's "infinite" with "mapname", "goniometric" and "projection".
#include <memory>
#include <optional>

#include "images/LinearImage.h"
#include "lights/Light.h"
#include "core/Transform.h"

namespace lenslab {

// An equirectangular environment: +z the pole, s = phi / (2 pi) across, t = theta / pi down. The
// map already carries L and scale. Sampled in proportion to luminance times sin(theta).
std::unique_ptr<Light> makeEnvironmentLight(LinearImage map, const Transform& lightToWorld);

// A point at the light-space origin with intensity I times the diagram's value at (phi, theta)
// about light-space +y; no diagram: a plain point light.
std::unique_ptr<Light> makeGoniometricLight(std::optional<LinearImage> diagram, Vec3f intensity,
                                            const Transform& lightToWorld);

// A point at the light-space origin projecting the image along +z through a pinhole whose field
// of view `fovDegrees` spans the image's shorter side; no image: a white frustum of aspect 1.
std::unique_ptr<Light> makeProjectionLight(std::optional<LinearImage> image, Vec3f intensity, float fovDegrees,
                                           const Transform& lightToWorld);

}  // namespace lenslab
