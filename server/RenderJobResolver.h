#pragma once
// Turns a render request into a job the renderer can run: the scene and lens ids resolved inside
// their folders, and the lens checked against the requested f-number and focus distance.
#include <string>

#include "LensStore.h"
#include "RenderRequest.h"
#include "JobRenderer.h"
#include "SceneCatalog.h"

namespace lenslab {

// HttpError 400 for an unknown scene or lens; OpticsError when the lens cannot be set that way.
RenderJobInput resolveRenderJob(const std::string& jobId, const RenderRequest& request, const LensStore& lenses,
                                const SceneCatalog& scenes);

}  // namespace lenslab
