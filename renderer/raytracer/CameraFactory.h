#pragma once
// Builds the scene's camera, applying the caller's overrides of the realistic camera.
#include <memory>

#include "Camera.h"
#include "Render.h"
#include "SceneDescription.h"

namespace lenslab {

// width/height: the full image in pixels; filmMarginPixels: the pixel filter's reach beyond it.
// Throws SceneError naming the Camera directive for bad or out-of-range parameters.
std::unique_ptr<Camera> makeCamera(SceneDescription& scene, const CameraOverrides& overrides, int width, int height,
                                   double filmMarginPixels);

// Where a lens table named in a scene is found: in the scene's folder tree, else (by file name)
// among lenslab's bundled lenses.
std::string findLensFile(const SceneDescription& scene, const std::string& name, const SourceLocation& where);

}  // namespace lenslab
