#pragma once
// The render queue: a bounded list of waiting jobs, a fixed number of workers, live progress
// (tiles done, the partial image), cancellation, and every state change persisted through the
// JobStore before it is visible. Finished images are written atomically before a job is done.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "jobs/JobRecord.h"
#include "jobs/JobStore.h"
#include "jobs/JobRenderer.h"
#include "core/ServiceConfig.h"

namespace lenslab {

class QueueFull : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct TileRect {
    int x0, y0, x1, y1;
};

// A job as clients see it: the record plus what only the live queue knows.
struct JobView {
    JobRecord record;
    bool cancelRequested = false;
    std::vector<TileRect> tiles;  // finished tiles in completion order (live jobs only)
};

struct QueueCounts {
    int queued = 0, running = 0, maxQueued = 0, workers = 0;
    std::uint64_t previewsEncoded = 0;  // partial images encoded as PNG since the start
};

using PreviewPng = std::shared_ptr<const std::vector<std::uint8_t>>;

class JobQueue {
public:
    JobQueue(JobStore& store, JobRenderer& renderer, const RenderLimits& limits, const std::string& imageDir);
    ~JobQueue();  // shutdown()

    // Records the job as queued and schedules it. QueueFull when maxQueued jobs already wait.
    JobRecord submit(const RenderJobInput& job);
    // Schedules a job already recorded as queued (after a restart), ignoring the limit.
    void restore(const JobRecord& record, const RenderJobInput& job);

    std::optional<JobView> find(const std::string& id) const;
    std::vector<JobView> recent(int limit) const;  // newest first

    enum class Cancel { Cancelled, Requested, AlreadyFinished, NotFound };
    Cancel cancel(const std::string& id);

    // Deletes a finished job: its image files, then its row. NotFound for unknown ids, Live for
    // jobs still waiting or running (cancel those first). StorageError when a file cannot be deleted.
    enum class Removal { Removed, Live, NotFound };
    Removal removeFinished(const std::string& id);
    // Bytes of a finished job's files on disk.
    std::uintmax_t imageBytes(const std::string& id) const;

    // Called after each job has finished and been saved (e.g. retention): on a worker thread after a
    // render, on the cancelling thread for a job cancelled while it waited.
    void setAfterJob(std::function<void()> afterJob);

    // The partial image of a running job as PNG (null before its first tile or when not running).
    // One encoding per version of the image at most once a second, shared by every reader: readers
    // arriving while it is under way wait for it (a 1920^2 partial image is 44 MB to copy, and
    // each reader used to copy and encode its own).
    PreviewPng preview(const std::string& id);

    // Where a finished job's image lies ("png" or "exr").
    std::string imagePath(const std::string& id, const std::string& format) const;

    QueueCounts counts() const;
    // The ids of the jobs waiting or running through lens `lensId` (its file must stay until they end).
    std::vector<std::string> liveJobsWithLens(const std::string& lensId) const;

    // Stops the workers: running renders are cancelled and return to the queue in the database,
    // so that the next start picks them up again. Idempotent.
    void shutdown();

private:
    struct LiveJob;
    static JobView viewOf(LiveJob& job);
    std::shared_ptr<LiveJob> liveJob(const std::string& id) const;
    void work();
    void runJob(const std::shared_ptr<LiveJob>& job);
    void finish(const std::shared_ptr<LiveJob>& job);
    void runAfterJob(const std::string& id);  // afterJob_, its errors logged

    JobStore& store_;
    JobRenderer& renderer_;
    RenderLimits limits_;
    std::string imageDir_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::shared_ptr<LiveJob>> waiting_;
    std::map<std::string, std::shared_ptr<LiveJob>> live_;  // waiting and running
    bool stopping_ = false;
    std::vector<std::thread> workers_;
    std::function<void()> afterJob_;
    std::atomic<std::uint64_t> previewsEncoded_{0};
};

}  // namespace lenslab
