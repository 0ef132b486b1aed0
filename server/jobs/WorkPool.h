#pragma once
// Heavy work of requests (analyses, previews, diagrams not in the cache, uploads' parsing) and report
// builds runs here, on a few threads of its own, not on the HTTP workers: 34 analyses of 4-7 s once
// held all 32 workers, and /api/health waited 156 s (issue 32). A request that needs heavy work is
// admitted first, then waits (its HTTP worker idle) for its result:
// - at most `admitted` requests wait on heavy work at once (running and queued), a quarter of the
//   HTTP workers by default (event streams may hold another quarter), so that half of them always
//   answer health, lists, downloads and cached results;
// - at most `perClient` of them from one client address, so one client cannot take every place;
// past either the answer is 429 with Retry-After, at once.
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "storage/ResultCache.h"

namespace lenslab {

struct WorkPoolLimits {
    int threads = 2;     // heavy work running at once
    int admitted = 16;   // requests waiting on heavy work at most, running ones included
    int perClient = 4;   // of those, from one client address
};

struct WorkPoolStats {
    int threads = 0, running = 0, queued = 0, admitted = 0;
    std::uint64_t refused = 0;  // requests answered 429
};

class WorkPool {
public:
    explicit WorkPool(const WorkPoolLimits& limits);
    ~WorkPool();  // lets the work already taken up finish, then joins the threads
    WorkPool(const WorkPool&) = delete;
    WorkPool& operator=(const WorkPool&) = delete;

    // A request's place among those waiting on heavy work, given back when it is destroyed.
    class Admission {
    public:
        Admission(WorkPool& pool, std::string client) : pool_(&pool), client_(std::move(client)) {}
        Admission(Admission&& other) noexcept : pool_(other.pool_), client_(std::move(other.client_)) { other.pool_ = nullptr; }
        Admission& operator=(Admission&&) = delete;
        ~Admission();

    private:
        WorkPool* pool_;
        std::string client_;
    };
    // HttpError 429 (Retry-After) when `client` holds its share already or the pool is full.
    Admission admit(const std::string& client);

    // Runs `work` on a pool thread; returns its result, or throws its exception, to the caller,
    // who waits (hold an Admission meanwhile).
    template <class Work>
    auto run(Work work) -> decltype(work()) {
        auto task = std::make_shared<std::packaged_task<decltype(work())()>>(std::move(work));
        auto result = task->get_future();
        post([task] { (*task)(); });
        return result.get();
    }

    // Queues work that nobody waits for (a report build); it runs in turn with the rest.
    void post(std::function<void()> work);

    // A result from `cache` (no admission needed), else admitted and computed by `compute` on a
    // pool thread; requests for a key being computed wait for that computation, admitted too.
    std::shared_ptr<const Bytes> cachedOrComputed(ResultCache& cache, const std::string& key, const std::string& client,
                                                  const std::function<Bytes()>& compute);

    WorkPoolStats stats() const;

private:
    void giveBack(const std::string& client);
    void work();

    const WorkPoolLimits limits_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::function<void()>> queue_;
    std::map<std::string, int> admittedByClient_;
    int admitted_ = 0, running_ = 0;
    std::uint64_t refused_ = 0;
    bool stopping_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace lenslab
