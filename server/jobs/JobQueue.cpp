#include "jobs/JobQueue.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <future>
#include <iostream>

#include "storage/AtomicFile.h"
#include "jobs/RenderJobResolver.h"
#include "storage/StorageError.h"
#include "core/WallClock.h"
#include "PublicMessage.h"

namespace lenslab {

namespace {

// A worker thread must outlive a full or read-only disk: a record that cannot be saved is logged
// and the job goes on in memory. Returns why it was not saved, in the client's words, or nullopt.
std::optional<std::string> saveOrLog(JobStore& store, const JobRecord& record) {
    try {
        store.save(record);
        return std::nullopt;
    } catch (const StorageError& e) {
        std::cerr << "lenslab serve: render " << record.id << " could not be saved: " << e.detail() << "\n";
        return std::string(e.what());
    } catch (const std::exception& e) {
        std::cerr << "lenslab serve: render " << record.id << " could not be saved: " << e.what() << "\n";
        return std::string("the server could not record the render; try again later");
    }
}

}  // namespace

namespace {

constexpr std::chrono::seconds kPreviewInterval{1};

}  // namespace

struct JobQueue::LiveJob {
    RenderJobInput input;
    std::atomic<bool> cancel{false};
    std::mutex mutex;  // guards everything below
    JobRecord record;
    std::vector<TileRect> tiles;
    Image partial;     // finished tiles copied in as they arrive
    int partialVersion = 0;
    PreviewPng previewPng;
    int previewVersion = -1;
    std::chrono::steady_clock::time_point previewEncodedAt;
    std::shared_future<PreviewPng> previewEncoding;  // valid while one is under way
};

namespace {

void copyTile(const TileUpdate& tile, const Image& source, Image& target) {
    if (target.width != source.width || target.height != source.height) {
        target.width = source.width;
        target.height = source.height;
        target.rgb.assign(source.rgb.size(), 0.0f);
    }
    const int x0 = std::clamp(tile.x0, 0, source.width), x1 = std::clamp(tile.x1, x0, source.width);
    const int y0 = std::clamp(tile.y0, 0, source.height), y1 = std::clamp(tile.y1, y0, source.height);
    for (int y = y0; y < y1; ++y) {
        const std::size_t row = (static_cast<std::size_t>(y) * source.width + x0) * 3;
        std::copy(source.rgb.begin() + row, source.rgb.begin() + row + (x1 - x0) * 3, target.rgb.begin() + row);
    }
}

}  // namespace

JobQueue::JobQueue(JobStore& store, JobRenderer& renderer, const RenderLimits& limits, const std::string& imageDir)
    : store_(store), renderer_(renderer), limits_(limits), imageDir_(imageDir) {
    std::filesystem::create_directories(imageDir_);
    for (int i = 0; i < std::max(1, limits_.concurrentRenders); ++i) workers_.emplace_back([this] { work(); });
}

JobQueue::~JobQueue() { shutdown(); }

JobRecord JobQueue::submit(const RenderJobInput& input) {
    auto job = std::make_shared<LiveJob>();
    job->input = input;
    job->record.id = input.jobId;
    job->record.request = renderRequestJson(input.request);
    job->record.created = secondsSinceEpoch();
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) throw QueueFull("the service is stopping");
    if (static_cast<int>(waiting_.size()) >= limits_.maxQueued)
        throw QueueFull("the render queue is full (" + std::to_string(waiting_.size()) +
                        " jobs waiting); try again when one has finished");
    store_.insert(job->record);
    waiting_.push_back(job);
    live_[input.jobId] = job;
    wake_.notify_one();
    return job->record;
}

void JobQueue::restore(const JobRecord& record, const RenderJobInput& input) {
    auto job = std::make_shared<LiveJob>();
    job->input = input;
    job->record = record;
    std::lock_guard<std::mutex> lock(mutex_);
    waiting_.push_back(job);
    live_[record.id] = job;
    wake_.notify_one();
}

std::optional<JobView> JobQueue::find(const std::string& id) const {
    const std::shared_ptr<LiveJob> job = liveJob(id);
    if (!job) {
        auto record = store_.find(id);
        if (!record) return std::nullopt;
        return JobView{*record, false, {}};
    }
    return viewOf(*job);
}

std::vector<JobView> JobQueue::recent(int limit) const {
    std::vector<JobView> views;
    for (const JobRecord& record : store_.recent(limit)) {
        const std::shared_ptr<LiveJob> job = liveJob(record.id);
        views.push_back(job ? viewOf(*job) : JobView{record, false, {}});
    }
    return views;
}

std::shared_ptr<JobQueue::LiveJob> JobQueue::liveJob(const std::string& id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = live_.find(id);
    return it == live_.end() ? nullptr : it->second;
}

JobView JobQueue::viewOf(LiveJob& job) {
    std::lock_guard<std::mutex> lock(job.mutex);
    return JobView{job.record, job.cancel.load(), job.tiles};
}

JobQueue::Cancel JobQueue::cancel(const std::string& id) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = live_.find(id);
        if (it == live_.end()) return store_.find(id) ? Cancel::AlreadyFinished : Cancel::NotFound;
        const std::shared_ptr<LiveJob> job = it->second;
        auto waitingAt = std::find(waiting_.begin(), waiting_.end(), job);
        if (waitingAt == waiting_.end()) {
            job->cancel = true;
            return Cancel::Requested;
        }
        waiting_.erase(waitingAt);
        {
            std::lock_guard<std::mutex> jobLock(job->mutex);
            job->record.state = JobState::Cancelled;
            job->record.finished = secondsSinceEpoch();
            saveOrLog(store_, job->record);  // out of the queue already: the cancel holds in memory
        }
        live_.erase(it);
    }
    // A job cancelled while waiting has finished too: submit and cancel must not pile up records.
    runAfterJob(id);
    return Cancel::Cancelled;
}

PreviewPng JobQueue::preview(const std::string& id) {
    const std::shared_ptr<LiveJob> job = liveJob(id);
    if (!job) return nullptr;
    std::promise<PreviewPng> encoding;
    Image snapshot;
    int version;
    {
        std::unique_lock<std::mutex> lock(job->mutex);
        if (job->partialVersion == 0) return nullptr;
        // Encoding a large image costs a good part of a second: readers get one at most per interval.
        const bool fresh = std::chrono::steady_clock::now() - job->previewEncodedAt < kPreviewInterval;
        if (job->previewVersion == job->partialVersion || (job->previewPng && fresh)) return job->previewPng;
        if (job->previewEncoding.valid()) {
            const std::shared_future<PreviewPng> pending = job->previewEncoding;
            lock.unlock();
            return pending.get();
        }
        job->previewEncoding = encoding.get_future().share();
        snapshot = job->partial;
        version = job->partialVersion;
    }
    PreviewPng png;
    try {
        png = std::make_shared<const std::vector<std::uint8_t>>(renderer_.encodePreview(snapshot));
        ++previewsEncoded_;
    } catch (...) {
        std::lock_guard<std::mutex> lock(job->mutex);
        job->previewEncoding = {};
        encoding.set_exception(std::current_exception());
        throw;
    }
    std::lock_guard<std::mutex> lock(job->mutex);
    job->previewPng = png;
    job->previewVersion = version;
    job->previewEncodedAt = std::chrono::steady_clock::now();
    job->previewEncoding = {};
    encoding.set_value(png);
    return png;
}

JobQueue::Removal JobQueue::removeFinished(const std::string& id) {
    std::lock_guard<std::mutex> lock(mutex_);  // a job cannot start or finish meanwhile
    if (live_.count(id)) return Removal::Live;
    if (!store_.find(id)) return Removal::NotFound;
    // Files first: a row without files reads as "image gone", files without a row would be lost.
    for (const char* format : {"png", "exr"}) {
        std::error_code error;
        std::filesystem::remove(imagePath(id, format), error);
        if (error) throw StorageError(storageErrorKind(error.value()), "cannot delete " + imagePath(id, format) + ": " + error.message());
    }
    store_.remove(id);
    return Removal::Removed;
}

std::uintmax_t JobQueue::imageBytes(const std::string& id) const {
    std::uintmax_t total = 0;
    for (const char* format : {"png", "exr"}) {
        std::error_code error;
        const auto size = std::filesystem::file_size(imagePath(id, format), error);
        if (!error) total += size;
    }
    return total;
}

void JobQueue::setAfterJob(std::function<void()> afterJob) {
    std::lock_guard<std::mutex> lock(mutex_);
    afterJob_ = std::move(afterJob);
}

std::string JobQueue::imagePath(const std::string& id, const std::string& format) const {
    return (std::filesystem::path(imageDir_) / (id + "." + format)).string();
}

QueueCounts JobQueue::counts() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return {static_cast<int>(waiting_.size()), static_cast<int>(live_.size() - waiting_.size()), limits_.maxQueued,
            static_cast<int>(workers_.size()), previewsEncoded_.load()};
}

std::vector<std::string> JobQueue::liveJobsWithLens(const std::string& lensId) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> ids;
    for (const auto& [id, job] : live_)
        if (job->input.request.lens == lensId) ids.push_back(id);
    return ids;
}

void JobQueue::shutdown() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        for (auto& entry : live_) entry.second->cancel = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_)
        if (t.joinable()) t.join();
}

void JobQueue::work() {
    for (;;) {
        std::shared_ptr<LiveJob> job;
        std::optional<std::string> notStarted;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || !waiting_.empty(); });
            if (stopping_) return;
            job = waiting_.front();
            waiting_.pop_front();
            std::lock_guard<std::mutex> jobLock(job->mutex);
            job->record.state = JobState::Running;
            job->record.started = secondsSinceEpoch();
            notStarted = saveOrLog(store_, job->record);
        }
        if (notStarted) {
            std::lock_guard<std::mutex> lock(job->mutex);
            job->record.state = JobState::Failed;
            job->record.error = *notStarted;
        } else {
            runJob(job);
        }
        finish(job);
        runAfterJob(job->record.id);
    }
}

void JobQueue::runAfterJob(const std::string& id) {
    std::function<void()> afterJob;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        afterJob = afterJob_;
    }
    try {
        if (afterJob) afterJob();
    } catch (const std::exception& e) {
        std::cerr << "lenslab serve: after render " << id << ": " << e.what() << "\n";
    }
}

void JobQueue::runJob(const std::shared_ptr<LiveJob>& job) {
    const auto onTile = [&job](const TileUpdate& tile, const Image& image) {
        std::lock_guard<std::mutex> lock(job->mutex);
        copyTile(tile, image, job->partial);
        ++job->partialVersion;
        job->tiles.push_back({tile.x0, tile.y0, tile.x1, tile.y1});
        job->record.tilesDone = tile.tilesDone;
        job->record.tilesTotal = tile.tilesTotal;
    };
    try {
        RenderedImages images = renderer_.render(job->input, onTile, job->cancel);
        writeFileAtomically(imagePath(job->record.id, "png"), images.png);
        writeFileAtomically(imagePath(job->record.id, "exr"), images.exr);
        std::lock_guard<std::mutex> lock(job->mutex);
        job->record.state = JobState::Done;
        job->record.stats = std::move(images.stats);
        job->record.warnings = std::move(images.warnings);
        job->record.imageBytes = static_cast<std::int64_t>(images.png.size() + images.exr.size());
    } catch (const RenderCancelled&) {
        bool stopping;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping = stopping_;
        }
        std::lock_guard<std::mutex> lock(job->mutex);
        job->record.state = stopping ? JobState::Queued : JobState::Cancelled;
    } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(job->mutex);
        job->record.state = JobState::Failed;
        std::cerr << "lenslab serve: render " << job->record.id << " failed: " << e.what() << "\n";
        job->record.error = publicMessage(e.what());
    } catch (...) {
        std::lock_guard<std::mutex> lock(job->mutex);
        job->record.state = JobState::Failed;
        job->record.error = "the renderer failed without a message";
    }
}

void JobQueue::finish(const std::shared_ptr<LiveJob>& job) {
    {
        std::lock_guard<std::mutex> lock(job->mutex);
        if (job->record.state == JobState::Queued) {
            job->record.started.reset();
            job->record.tilesDone = 0;
        } else {
            job->record.finished = secondsSinceEpoch();
        }
        saveOrLog(store_, job->record);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    live_.erase(job->record.id);
}

}  // namespace lenslab
