#pragma once
// The outcome of checking a render request against its scene's camera and lens, remembered per
// scene, lens and camera settings. A check reads the scene's options block and the lens and runs
// the optics (about a millisecond); the web page submits the same settings again and again, and
// neither a bundled scene nor a stored lens changes under its id while the service runs.
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

#include "jobs/JobRenderer.h"

namespace lenslab {

class RenderSettingsChecks {
public:
    // HttpError 422 naming the scene's line or the request's field, as the render would fail; the
    // same answer again for the same scene, lens and settings.
    void check(const RenderJobInput& job);

private:
    static constexpr std::size_t kMaxEntries = 4096;  // then forgotten all at once: a bound, not an LRU
    std::mutex mutex_;
    std::unordered_map<std::string, std::optional<std::string>> outcomes_;  // key -> the 422's message, or none
};

}  // namespace lenslab
