#pragma once
// Render jobs in SQLite: every state change is written before it is reported, so a restart finds
// the jobs as the clients last saw them.
#include <optional>
#include <vector>

#include "storage/Database.h"
#include "jobs/JobRecord.h"

namespace lenslab {

class JobStore {
public:
    explicit JobStore(Database& database);

    void insert(const JobRecord& job);
    void save(const JobRecord& job);  // state, times, error, progress, stats
    std::optional<JobRecord> find(const std::string& id) const;
    std::vector<JobRecord> recent(int limit) const;  // newest first
    std::vector<JobRecord> queued() const;           // oldest first
    std::vector<JobRecord> finished() const;         // done, failed or cancelled; oldest finish first
    bool remove(const std::string& id);              // false when there was no such job

    // After an abrupt stop: jobs left running are marked failed and interrupted (to be
    // resubmitted). Returns how many.
    int markInterrupted();

private:
    Database& database_;
};

}  // namespace lenslab
