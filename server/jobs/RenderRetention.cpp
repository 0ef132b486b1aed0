#include "jobs/RenderRetention.h"

#include <iostream>
#include <string>
#include <vector>

#include "storage/StorageError.h"

namespace lenslab {

int collectRenders(JobQueue& jobs, const JobStore& store, const RetentionPolicy& policy, double now) {
    int removed = 0;
    const auto removeAll = [&](const std::vector<std::string>& ids) {
        for (const std::string& id : ids) {
            try {
                removed += jobs.removeFinished(id) == JobQueue::Removal::Removed;
            } catch (const StorageError& e) {
                // Runs after a job ends, not for a client: a file that cannot be deleted is left for the operator.
                std::cerr << "lenslab serve: retention: " << e.detail() << "\n";
            }
        }
    };
    if (policy.keepDays > 0) removeAll(store.finishedBefore(now - policy.keepDays * 86400.0));
    if (policy.keepCount > 0) {
        const int surplus = store.finishedCount() - policy.keepCount;
        if (surplus > 0) removeAll(store.oldestFinished(surplus));
    }
    if (policy.keepBytes > 0) removeAll(store.finishedBeyondBytes(static_cast<std::int64_t>(policy.keepBytes)));
    return removed;
}

}  // namespace lenslab
