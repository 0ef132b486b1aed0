#pragma once
// One render job as the database keeps it.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

enum class JobState { Queued, Running, Done, Failed, Cancelled };

const char* jobStateName(JobState state);  // queued | running | done | failed | cancelled
JobState parseJobState(const std::string& name);

struct JobRecord {
    std::string id;
    nlohmann::json request;  // renderRequestJson
    JobState state = JobState::Queued;
    double created = 0;      // seconds since the epoch
    std::optional<double> started, finished;
    std::string error;       // failed: why
    bool interrupted = false;  // the service stopped abruptly while it rendered
    int tilesDone = 0, tilesTotal = 0;
    nlohmann::json stats = nlohmann::json::object();
    std::vector<std::string> warnings;  // done: what the picture does not show (RenderOutput::warnings)
    std::int64_t imageBytes = 0;  // done: its PNG and EXR on disk, for the retention's size limit
};

}  // namespace lenslab
