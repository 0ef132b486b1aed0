// checkRenderSettings: the camera's checks of renderScene, on the scene's options block alone.
#include "Render.h"
#include "cameras/CameraFactory.h"
#include "film/SensorReadout.h"
#include "scene/SceneDescription.h"

namespace lenslab {

void checkRenderSettings(const RenderSettings& settings) {
    SceneParseOptions options;
    options.confined = settings.confined;
    options.optionsOnly = true;
    SceneDescription scene = parseSceneFile(settings.scenePath, options);
    if (settings.sensor) {
        if (scene.camera.type != "realistic") throw SceneError(sensorWithoutLens(scene.camera.type));
        sensorFilmDiagonalMm(*settings.sensor, settings.camera.filmDiagonal, settings.width.value_or(scene.film.xresolution),
                             settings.height.value_or(scene.film.yresolution));
    }
    checkCameraSettings(scene, settings.camera);
}

}  // namespace lenslab
