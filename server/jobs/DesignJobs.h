#pragma once
// Optimisation and tolerancing jobs (POST /api/lenses/{id}/optimise and .../tolerance): each runs in
// the heavy-work pool, off the HTTP workers, holding its client's place there (the per-client share)
// until it ends; its progress and result are kept in memory (a restart forgets them: a job takes
// seconds, and resubmitting it gives the same answer). Cancellation is polled by the design library
// between merit evaluations and trials, so a DELETE stops a running job within milliseconds.
#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "jobs/WorkPool.h"

namespace lenslab {

// What the work sees of its job: whether it should stop, and where to put its progress.
class DesignJobControl {
public:
    virtual ~DesignJobControl() = default;
    virtual bool cancelled() const = 0;
    virtual void report(nlohmann::json progress) = 0;  // replaces the job's "progress"; any thread
};

// The job's result (null when it was cancelled); throws to fail the job with the message.
using DesignWork = std::function<nlohmann::json(DesignJobControl&)>;

struct DesignJobView {
    nlohmann::json status;  // {"id", "kind", "lens", "state", "progress", "created", "started", "finished", "result"|"error"}
    std::uint64_t version;  // rises with every change of state or progress
    bool over;              // done, failed or cancelled
};

class DesignJobs {
public:
    // Finished jobs kept at most; the oldest finished is forgotten first.
    static constexpr std::size_t kKeptFinished = 64;

    explicit DesignJobs(WorkPool& pool) : pool_(pool) {}
    ~DesignJobs();  // cancels every job and waits for those the pool holds (the pool must outlive this)
    DesignJobs(const DesignJobs&) = delete;
    DesignJobs& operator=(const DesignJobs&) = delete;

    // Queues `work` under a new id ("design-" and 16 hex digits); `admission` is given back when it ends.
    DesignJobView start(const std::string& kind, const std::string& lensId, WorkPool::Admission admission, DesignWork work);

    std::optional<DesignJobView> find(const std::string& id) const;

    // A queued job is cancelled at once, a running one at its next poll; a finished one is forgotten.
    enum class Cancel { Cancelled, Requested, Deleted, NotFound };
    Cancel cancel(const std::string& id);

private:
    struct Job;
    class Control;
    void run(const std::shared_ptr<Job>& job, const DesignWork& work);
    void finish(Job& job, const std::string& state, nlohmann::json outcome);  // under mutex_
    DesignJobView viewOf(const Job& job) const;                               // under mutex_

    WorkPool& pool_;
    mutable std::mutex mutex_;
    std::condition_variable idle_;
    std::map<std::string, std::shared_ptr<Job>> jobs_;
    std::deque<std::string> finishedOrder_;  // oldest first
    int inPool_ = 0;                         // runs posted and not yet returned
};

}  // namespace lenslab
