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
    void save(const JobRecord& job);  // state, times, error, progress, stats, warnings
    std::optional<JobRecord> find(const std::string& id) const;
    std::vector<JobRecord> recent(int limit) const;  // newest first
    std::vector<JobRecord> queued() const;           // oldest first
    bool remove(const std::string& id);              // false when there was no such job

    // The finished jobs (done, failed or cancelled) past one retention limit, by id, oldest finish
    // first. Each asks the database for those alone: a pass reads none of the jobs it keeps.
    std::vector<std::string> finishedBefore(double time) const;
    std::vector<std::string> oldestFinished(int count) const;
    std::vector<std::string> finishedBeyondBytes(std::int64_t keptBytes) const;  // the newest keptBytes stay
    int finishedCount() const;

    // Jobs recorded before the image size was (a database of an earlier version): measured once at start.
    std::vector<std::string> withoutImageBytes() const;
    void setImageBytes(const std::string& id, std::int64_t bytes);

    // After an abrupt stop: jobs left running are marked failed and interrupted (to be
    // resubmitted). Returns how many.
    int markInterrupted();

private:
    Database& database_;
};

}  // namespace lenslab
