#include "jobs/RenderJobResolver.h"


#include "core/HttpError.h"

namespace lenslab {

RenderJobInput resolveRenderJob(const std::string& jobId, const RenderRequest& request, const LensStore& lenses,
                                const SceneCatalog& scenes, RenderSettingsChecks& checks) {
    const auto scene = scenes.find(request.scene);
    if (!scene) throw HttpError(400, "no scene with id '" + request.scene + "' (see GET /api/scenes)");
    const auto lens = lenses.find(request.lens);
    if (!lens) throw HttpError(400, "no lens with id '" + request.lens + "' (see GET /api/lenses)");
    RenderJobInput input{jobId, request, scene->path, lens->path, lens->system.layout};
    checks.check(input);
    return input;
}

RenderSettings renderSettings(const RenderJobInput& job) {
    RenderSettings settings;
    settings.scenePath = job.scenePath;
    settings.confined = true;
    settings.camera.lensFile = job.lensPath;
    settings.camera.lensLayout = job.lensLayout;
    const LensSettings lens = lensSettings(job.request);
    settings.camera.fstop = lens.fstop;
    settings.camera.focusDistance = lens.focusDistance;
    settings.camera.filmDiagonal = job.request.filmDiagonal;
    settings.camera.mode = job.request.mode;
    settings.camera.spectral = job.request.spectral;
    settings.camera.ghosts = job.request.ghosts;
    settings.camera.ghostModel = job.request.ghostModel;
    settings.camera.tiltDegrees = job.request.tilt;
    settings.camera.swingDegrees = job.request.swing;
    settings.camera.shiftMm = job.request.shift;
    if (job.request.sensor) settings.sensor = sensorSpecFromPairs(*job.request.sensor);
    settings.spp = job.request.spp;
    settings.width = job.request.width;
    settings.height = job.request.height;
    return settings;
}

}  // namespace lenslab
