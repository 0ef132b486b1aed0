// The worker loop. Only this (main) thread calls MPI (MPI_THREAD_FUNNELED): setup and tile
// rendering run on one long-lived helper thread while the main thread sends heartbeats, so rank 0
// can tell a busy worker from a dead one.
#include "MpiTileWorker.h"

#include <mpi.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <future>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "render/PreparedFrame.h"
#include "TileMessages.h"

namespace lenslab {

namespace {

using Clock = std::chrono::steady_clock;

// The longest rank 0 may take for its own frame setup, before it first answers.
constexpr double kFirstAnswerLimitSeconds = 600;

// Rank 0 is gone or stuck: nothing left to report to.
class MasterSilent : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Runs one piece of work at a time on the same thread for the worker's whole life. TBB's worker
// threads join an arena used from a fresh thread per tile only now and then (measured: a 2-thread
// worker rendered at 1-thread speed); from a long-lived thread they always do.
class HelperThread {
public:
    HelperThread() : thread_([this] { loop(); }) {}
    ~HelperThread() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    HelperThread(const HelperThread&) = delete;
    HelperThread& operator=(const HelperThread&) = delete;

    template <class Work>
    auto run(Work work) {
        auto task = std::make_shared<std::packaged_task<decltype(work())()>>(std::move(work));
        auto result = task->get_future();
        {
            std::lock_guard<std::mutex> lock(mutex_);
            next_ = [task] { (*task)(); };
        }
        wake_.notify_all();
        return result;
    }

private:
    void loop() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stopping_ || next_; });
            if (!next_) return;
            std::function<void()> work = std::move(next_);
            next_ = nullptr;
            lock.unlock();
            work();
            lock.lock();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_;
    std::function<void()> next_;
    bool stopping_ = false;
    std::thread thread_;  // last: starts once the members above exist
};

class WorkerLink {
public:
    explicit WorkerLink(const MpiRenderOptions& options)
        : heartbeat_(std::chrono::duration<double>(options.workerTimeoutSeconds / 4)),
          answerLimit_(options.workerTimeoutSeconds) {}

    void send(mpi::Tag tag, const void* bytes, int size) {
        MPI_Send(bytes, size, MPI_BYTE, 0, tag, MPI_COMM_WORLD);
        lastSent_ = Clock::now();
    }
    void sendText(mpi::Tag tag, const std::string& text) { send(tag, text.data(), int(text.size())); }

    // Runs work on the helper thread, sending heartbeats until it is done.
    template <class Work>
    auto whileBeating(Work work) {
        auto future = helper_.run(std::move(work));
        while (future.wait_for(heartbeat_) != std::future_status::ready) beat();
        return future.get();
    }

    struct Answer {
        int tile = -1;      // >= 0: render this tile
        bool stop = false;
        bool finalize = true;
    };

    // Waits for rank 0's Tile or Stop; its Wait messages restart the clock. Before its first answer
    // rank 0 may still be setting up its own frame.
    Answer awaitAnswer() {
        auto start = Clock::now();
        const double limit = answered_ ? answerLimit_ : std::max(answerLimit_, kFirstAnswerLimitSeconds);
        for (;;) {
            int flag = 0;
            MPI_Status status;
            MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
            if (flag) {
                int value = 0;
                MPI_Recv(&value, 1, MPI_INT, 0, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                answered_ = true;
                start = Clock::now();
                if (status.MPI_TAG == mpi::kWait) continue;
                if (status.MPI_TAG == mpi::kTile) return {value, false, true};
                return {-1, true, value != mpi::kSkipFinalize};
            }
            if (std::chrono::duration<double>(Clock::now() - start).count() > limit)
                throw MasterSilent("rank 0 gave no answer for " + std::to_string(int(limit)) + " s");
            if (Clock::now() - lastSent_ > heartbeat_) beat();
            std::this_thread::sleep_for(std::chrono::microseconds(500));
        }
    }

private:
    void beat() { send(mpi::kHeartbeat, nullptr, 0); }

    HelperThread helper_;
    std::chrono::duration<double> heartbeat_;
    double answerLimit_;
    bool answered_ = false;
    Clock::time_point lastSent_ = Clock::now();
};

// Test hook (tests/mpi): LENSLAB_MPI_TEST_KILL_RANK=r and LENSLAB_MPI_TEST_KILL_AFTER_TILES=n make
// worker rank r kill itself (SIGKILL) when it is handed a tile after finishing n tiles.
bool testHookKills(int rank, int tilesRendered) {
    const char* killRank = std::getenv("LENSLAB_MPI_TEST_KILL_RANK");
    const char* killAfter = std::getenv("LENSLAB_MPI_TEST_KILL_AFTER_TILES");
    return killRank && killAfter && std::atoi(killRank) == rank && std::atoi(killAfter) == tilesRendered;
}

// The tile's rows in parallel, each through the frame's shared render routine.
std::vector<unsigned char> renderTileResult(PreparedFrame& frame, int tileIndex) {
    const PixelRect& tile = frame.tiles()[std::size_t(tileIndex)];
    const int width = tile.x1 - tile.x0, height = tile.y1 - tile.y0;
    const std::size_t pixelBytes = sizeof(float) * 3 * std::size_t(width) * height;
    std::vector<unsigned char> message(sizeof(mpi::TileResultHeader) + pixelBytes);
    float* pixels = reinterpret_cast<float*>(message.data() + sizeof(mpi::TileResultHeader));
    std::vector<TileCounters> rowCounters(static_cast<std::size_t>(height));
    std::vector<SplatBuffer> rowSplats(static_cast<std::size_t>(height));
    frame.arena().execute([&] {
        tbb::parallel_for(0, height, [&](int row) {
            const PixelRect rect{tile.x0, tile.y0 + row, tile.x1, tile.y0 + row + 1};
            frame.renderRect(rect, pixels + std::size_t(row) * width * 3, std::size_t(width) * 3, rowCounters[row],
                             rowSplats[row]);
        });
    });
    TileCounters sum;
    for (const auto& c : rowCounters) sum += c;
    // The rows' splats added in row order, as a whole-tile render adds them.
    SplatBuffer splats;
    for (const auto& s : rowSplats) splats.add(s);
    message.resize(message.size() + sizeof(float) * splats.rgb().size());
    std::memcpy(message.data() + sizeof(mpi::TileResultHeader) + pixelBytes, splats.rgb().data(),
                sizeof(float) * splats.rgb().size());
    mpi::TileResultHeader head;
    head.tileIndex = tileIndex;
    const PixelRect& box = splats.box();
    head.splatBox[0] = box.x0;
    head.splatBox[1] = box.y0;
    head.splatBox[2] = box.x1;
    head.splatBox[3] = box.y1;
    head.cameraRays = sum.cameraRays;
    head.blockedCameraRays = sum.blockedCameraRays;
    head.raysTraced = sum.raysTraced;
    std::memcpy(message.data(), &head, sizeof head);
    return message;
}

}  // namespace

bool runTileWorker(const RenderSettings& settings, const MpiRenderOptions& options) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    WorkerLink link(options);
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    link.sendText(mpi::kHello, std::string(host) + " pid " + std::to_string(::getpid()));

    const mpi::TileResultHeader noTile;
    std::vector<unsigned char> result(sizeof noTile);
    std::memcpy(result.data(), &noTile, sizeof noTile);
    try {
        const auto frame = link.whileBeating([&] { return std::make_unique<PreparedFrame>(settings); });
        for (int tilesRendered = 0;; ++tilesRendered) {
            link.send(mpi::kRequest, result.data(), int(result.size()));
            const WorkerLink::Answer answer = link.awaitAnswer();
            if (answer.stop) return answer.finalize;
            if (answer.tile >= int(frame->tiles().size()))
                throw std::runtime_error("rank 0 sent tile " + std::to_string(answer.tile) + ", which the frame lacks");
            if (testHookKills(rank, tilesRendered)) std::raise(SIGKILL);
            result = link.whileBeating([&] { return renderTileResult(*frame, answer.tile); });
        }
    } catch (const MasterSilent& e) {
        std::fprintf(stderr, "lenslab: MPI worker rank %d: %s; stopping the job\n", rank, e.what());
        MPI_Abort(MPI_COMM_WORLD, 1);
        return false;
    } catch (const std::exception& e) {
        link.sendText(mpi::kFailed, e.what());
        const WorkerLink::Answer answer = link.awaitAnswer();
        if (!answer.stop) throw std::runtime_error("rank 0 sent a tile after this worker failed");
        return answer.finalize;
    }
}

}  // namespace lenslab
