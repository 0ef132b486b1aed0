#include "jobs/WorkPool.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>

#include "core/HttpError.h"

namespace lenslab {

namespace {

// Heavy work gives the CPU to the HTTP workers' short answers (health, lists, cached results,
// downloads) when both want it, and runs as fast on an idle machine. Threads it starts (llvmpipe's
// for a diagram) inherit the niceness.
void yieldToTheHttpWorkers() { ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10); }

}  // namespace

WorkPool::WorkPool(const WorkPoolLimits& limits) : limits_(limits) {
    for (int i = 0; i < std::max(1, limits.threads); ++i) threads_.emplace_back([this] { work(); });
}

WorkPool::~WorkPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

WorkPool::Admission::~Admission() {
    if (pool_) pool_->giveBack(client_);
}

WorkPool::Admission WorkPool::admit(const std::string& client) {
    std::lock_guard<std::mutex> lock(mutex_);
    int& mine = admittedByClient_[client];
    if (mine >= limits_.perClient || admitted_ >= limits_.admitted) {
        const bool share = mine >= limits_.perClient;
        if (mine == 0) admittedByClient_.erase(client);
        ++refused_;
        if (share)
            throw HttpError(429, "this client has " + std::to_string(limits_.perClient) +
                                     " requests of heavy work (analyses, previews, diagrams, uploads) in progress, its "
                                     "share; send the next when one has been answered", 1);
        throw HttpError(429, "the server is busy with heavy work (" + std::to_string(limits_.admitted) +
                                 " analyses, previews, diagrams or uploads in progress); try again shortly", 2);
    }
    ++mine;
    ++admitted_;
    return Admission(*this, client);
}

void WorkPool::giveBack(const std::string& client) {
    std::lock_guard<std::mutex> lock(mutex_);
    --admitted_;
    if (--admittedByClient_[client] == 0) admittedByClient_.erase(client);
}

void WorkPool::post(std::function<void()> work) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.push_back(std::move(work));
    }
    wake_.notify_one();
}

std::shared_ptr<const Bytes> WorkPool::cachedOrComputed(ResultCache& cache, const std::string& key,
                                                         const std::string& client,
                                                         const std::function<Bytes()>& compute) {
    if (auto hit = cache.cached(key)) return hit;
    const Admission admission = admit(client);
    return cache.getOrCompute(key, [&] { return run(compute); });
}

void WorkPool::work() {
    yieldToTheHttpWorkers();
    for (;;) {
        std::function<void()> next;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
            if (queue_.empty()) return;  // stopping, and nothing is left to do
            next = std::move(queue_.front());
            queue_.pop_front();
            ++running_;
        }
        next();  // a packaged task or a job that catches its own exceptions
        std::lock_guard<std::mutex> lock(mutex_);
        --running_;
    }
}

WorkPoolStats WorkPool::stats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return {static_cast<int>(threads_.size()), running_, static_cast<int>(queue_.size()), admitted_, refused_};
}

}  // namespace lenslab
