#include "jobs/RenderRetention.h"

#include <iostream>
#include <numeric>
#include <vector>

#include "storage/StorageError.h"

namespace lenslab {

int collectRenders(JobQueue& jobs, const JobStore& store, const RetentionPolicy& policy, double now) {
    const std::vector<JobRecord> finished = store.finished();  // oldest first
    std::vector<std::uintmax_t> bytes;
    for (const JobRecord& job : finished) bytes.push_back(jobs.imageBytes(job.id));
    std::uintmax_t total = std::accumulate(bytes.begin(), bytes.end(), std::uintmax_t{0});
    const double oldestKept = policy.keepDays > 0 ? now - policy.keepDays * 86400.0 : -1e300;
    int removed = 0;
    for (std::size_t i = 0; i < finished.size(); ++i) {
        const bool tooOld = finished[i].finished.value_or(finished[i].created) < oldestKept;
        const bool overSize = policy.keepBytes > 0 && total > policy.keepBytes;
        if (!tooOld && !overSize) break;
        try {
            if (jobs.removeFinished(finished[i].id) != JobQueue::Removal::Removed) continue;
        } catch (const StorageError& e) {
            // Runs on render threads: a file that cannot be deleted is left for the operator.
            std::cerr << "lenslab serve: retention: " << e.detail() << "\n";
            continue;
        }
        total -= bytes[i];
        ++removed;
    }
    return removed;
}

}  // namespace lenslab
