#pragma once
// Builds the scene's camera, applying the caller's overrides of the realistic camera.
#include <memory>

#include "cameras/Camera.h"
#include "Render.h"
#include "scene/SceneDescription.h"

namespace lenslab {

// width/height: the full image in pixels; filmMarginPixels: the pixel filter's reach beyond it.
// Throws SceneError naming the Camera directive for bad or out-of-range parameters. A lens file is
// resolved like every file the scene names (resolveScenePath), never looked up elsewhere.
// A set *cancel stops a realistic camera's setup with RenderCancelled. A camera that moves during the
// exposure is a MovingCamera around the one built in camera space.
std::unique_ptr<Camera> makeCamera(SceneDescription& scene, const CameraOverrides& overrides, int width, int height,
                                   double filmMarginPixels, const std::atomic<bool>* cancel = nullptr);

// The checks makeCamera makes of the scene's camera and the overrides, without its setup (a realistic
// camera's lens is read and its aperture and focus checked; the exit pupil is not measured): the same
// SceneError makeCamera would throw, in milliseconds.
void checkCameraSettings(SceneDescription& scene, const CameraOverrides& overrides);

}  // namespace lenslab
