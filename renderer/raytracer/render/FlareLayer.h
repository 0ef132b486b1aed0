#pragma once
// A frame's lens flare: the ghosts its realistic camera asks for (RealisticParams::ghosts: the
// scene's camera parameters or the render settings), of the emitters found for them
// (render/FlareSources.h), as an image layer the frame adds to its pixels.
#include <atomic>
#include <string>
#include <vector>

#include "Render.h"
#include "cameras/LensFlare.h"
#include "film/SpectralSensor.h"
#include "geometry/SceneGeometry.h"

namespace lenslab {

struct FlareLayer {
    std::vector<float> rgb;       // full image, RGB per pixel; empty: no flare (nothing added)
    FlareStats stats;
    std::string description;      // for the image's metadata
};

// Empty for any other camera than a still realistic one, and when its selection is off, or auto
// and no emitter is bright enough. SceneError when the settings ask for ghosts (all, N) of a
// camera that moves during the exposure. RenderCancelled once *cancel is set.
FlareLayer makeFlareLayer(const Camera& camera, const CameraOverrides& overrides, const SceneGeometry& geometry, int width,
                          int height, const SpectralSensor& sensor, float time, const std::atomic<bool>* cancel);

}  // namespace lenslab
