#include "jobs/RenderSettingsChecks.h"

#include "core/HttpError.h"
#include "settings/LensAnalysis.h"
#include "prescription/OpticsError.h"
#include "jobs/RenderJobResolver.h"
#include "PublicMessage.h"

namespace lenslab {

namespace {

// What the check depends on: the files and the settings that reach the camera (not spp or size).
std::string checkKey(const RenderJobInput& job) {
    nlohmann::json key = renderRequestJson(job.request);
    for (const char* unused : {"spp", "width", "height", "scene", "lens"}) key.erase(unused);
    return job.scenePath + '\n' + job.lensPath + '\n' + std::to_string(static_cast<int>(job.lensLayout)) + '\n' + key.dump();
}

// The 422's message, or none when the render can start.
std::optional<std::string> checkOutcome(const RenderJobInput& job) {
    try {
        checkRenderSettings(renderSettings(job));
        return std::nullopt;
    } catch (const SceneError& e) {
        return publicMessage(e.what());
    } catch (const OpticsError& e) {
        return publicMessage(e.what());
    }
}

}  // namespace

void RenderSettingsChecks::check(const RenderJobInput& job) {
    const std::string key = checkKey(job);
    std::optional<std::optional<std::string>> known;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (const auto it = outcomes_.find(key); it != outcomes_.end()) known = it->second;
    }
    if (!known) {
        known = checkOutcome(job);  // outside the lock: checks of other settings run side by side
        std::lock_guard<std::mutex> lock(mutex_);
        if (outcomes_.size() >= kMaxEntries) outcomes_.clear();
        outcomes_.emplace(key, *known);
    }
    if (*known) throw HttpError(422, **known);
}

}  // namespace lenslab
