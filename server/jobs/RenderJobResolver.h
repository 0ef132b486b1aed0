#pragma once
// Turns a render request into a job the renderer can run: the scene and lens ids resolved inside
// their folders, and the request checked with the scene's own camera settings before it is queued.
#include <string>

#include "storage/LensStore.h"
#include "jobs/RenderRequest.h"
#include "jobs/JobRenderer.h"
#include "Render.h"
#include "jobs/RenderSettingsChecks.h"
#include "storage/SceneCatalog.h"

namespace lenslab {

// HttpError 400 for an unknown scene or lens; HttpError 422 when the request's or the scene's own
// settings (f-number, focus, film) do not fit the lens, or the scene's camera takes no lens, as the
// render would fail (checks remembers the outcome).
RenderJobInput resolveRenderJob(const std::string& jobId, const RenderRequest& request, const LensStore& lenses,
                                const SceneCatalog& scenes, RenderSettingsChecks& checks);

// The renderer's settings for a job (all but the thread count).
RenderSettings renderSettings(const RenderJobInput& job);

}  // namespace lenslab
