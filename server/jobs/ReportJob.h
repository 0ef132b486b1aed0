#pragma once
// The service's report build: one at a time, in the heavy-work pool, with progress and
// cancellation, writing into the folder served at /report/ (buildReport's cache makes rebuilds cheap).
#include <nlohmann/json.hpp>

#include <atomic>
#include <future>
#include <mutex>

#include "BuildReport.h"
#include "jobs/WorkPool.h"

namespace lenslab {

class ReportJob {
public:
    explicit ReportJob(WorkPool& pool) : pool_(pool) {}
    ~ReportJob();  // cancels a running build and waits for it (the pool must outlive this)
    ReportJob(const ReportJob&) = delete;
    ReportJob& operator=(const ReportJob&) = delete;

    // Starts a build; HttpError 409 while one is running.
    void start(const ReportOptions& options);
    // Asks a running build to stop; false when none is running.
    bool cancel();
    // {"state": idle|running|done|failed|cancelled, "progress": {...}, "summary"|"error", times}.
    nlohmann::json status() const;

private:
    void run(ReportOptions options);

    WorkPool& pool_;
    mutable std::mutex mutex_;
    std::future<void> build_;
    std::atomic<bool> cancel_{false};
    std::string state_ = "idle";
    ReportProgress progress_;
    nlohmann::json outcome_;  // summary or error
    double started_ = 0, finished_ = 0;
};

}  // namespace lenslab
