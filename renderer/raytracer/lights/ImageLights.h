#pragma once
// Lights whose emission an image shapes, each in the light's own space (the current transform at
// LightSource): pbrt-v3's "infinite" with "mapname", "goniometric" and "projection".
#include <memory>
#include <optional>

#include "images/LinearImage.h"
#include "lights/Light.h"
#include "core/Transform.h"

namespace lenslab {

// How an image covers the sphere of directions: pbrt-v3's equirectangular (+z the pole, s = phi /
// (2 pi) across, t = theta / pi down) or pbrt-v4's equal-area square (sampling/EqualAreaSphere.h,
// s across, t down).
enum class SphereLayout { Equirectangular, EqualArea };

// An environment map around the scene. The map already carries L and scale. Sampled in proportion
// to luminance times each texel's solid angle.
std::unique_ptr<Light> makeEnvironmentLight(LinearImage map, const Transform& lightToWorld,
                                            SphereLayout layout = SphereLayout::Equirectangular);

// A point at the light-space origin with intensity I times the diagram's value in each direction,
// light-space +y its pole (both pbrt versions swap y and z before the layout's mapping); no
// diagram: a plain point light.
std::unique_ptr<Light> makeGoniometricLight(std::optional<LinearImage> diagram, Vec3f intensity,
                                            const Transform& lightToWorld,
                                            SphereLayout layout = SphereLayout::Equirectangular);

// A point at the light-space origin projecting the image along +z through a pinhole whose field
// of view `fovDegrees` spans the image's shorter side; no image: a white frustum of aspect 1.
std::unique_ptr<Light> makeProjectionLight(std::optional<LinearImage> image, Vec3f intensity, float fovDegrees,
                                           const Transform& lightToWorld);

}  // namespace lenslab
