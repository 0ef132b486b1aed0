#include "RenderJobResolver.h"

#include <limits>

#include "HttpError.h"
#include "LensAnalysis.h"

namespace lenslab {

RenderJobInput resolveRenderJob(const std::string& jobId, const RenderRequest& request, const LensStore& lenses,
                                const SceneCatalog& scenes) {
    const auto scene = scenes.find(request.scene);
    if (!scene) throw HttpError(400, "no scene with id '" + request.scene + "' (see GET /api/scenes)");
    const auto lens = lenses.find(request.lens);
    if (!lens) throw HttpError(400, "no lens with id '" + request.lens + "' (see GET /api/lenses)");
    analyzeLens(lens->system, lensSettings(request));
    return {jobId, request, scene->path, lens->path, lens->system.layout};
}

}  // namespace lenslab
