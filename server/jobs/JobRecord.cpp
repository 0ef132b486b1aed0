#include "jobs/JobRecord.h"

#include <stdexcept>

namespace lenslab {

const char* jobStateName(JobState state) {
    switch (state) {
        case JobState::Queued: return "queued";
        case JobState::Running: return "running";
        case JobState::Done: return "done";
        case JobState::Failed: return "failed";
        case JobState::Cancelled: return "cancelled";
    }
    return "failed";
}

JobState parseJobState(const std::string& name) {
    for (JobState s : {JobState::Queued, JobState::Running, JobState::Done, JobState::Failed, JobState::Cancelled})
        if (name == jobStateName(s)) return s;
    throw std::runtime_error("unknown job state '" + name + "' in the database");
}

}  // namespace lenslab
