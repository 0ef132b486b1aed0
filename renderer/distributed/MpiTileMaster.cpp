// The master loop polls (MPI_Iprobe, then a short sleep) rather than blocking in MPI_Recv: Open
// MPI's blocking receive spins, and rank 0 shares a node's cores with workers.
#include "MpiTileMaster.h"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "MasterSignalNote.h"
#include "TileMessages.h"
#include "render/RenderWarnings.h"
#include "render/SplatImage.h"

namespace lenslab {

namespace {

using Clock = std::chrono::steady_clock;

struct WorkerState {
    std::string where = "?";     // host and pid, from its Hello
    Clock::time_point lastHeard;
    Clock::time_point lastToldToWait;
    int tile = -1;               // handed out and not yet returned
    int tilesDone = 0;
    bool waiting = false;        // asked for a tile, none given yet
    bool alive = true;
    bool parked = false;         // reported an error and waits for Stop at the end
    bool lost = false;           // fell silent: dead or hung
    std::string failure;
};

void sendInt(int rank, mpi::Tag tag, int value) { MPI_Send(&value, 1, MPI_INT, rank, tag, MPI_COMM_WORLD); }

class TileMaster {
public:
    TileMaster(const PreparedFrame& frame, const MpiRenderOptions& options,
               const std::function<void(const TileUpdate&, const Image&)>& onTile)
        : frame_(frame), options_(options), onTile_(onTile), done_(frame.tiles().size(), false),
          splats_(frame.tiles().size()) {
        int size = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        workers_.resize(std::size_t(size));  // index = rank; rank 0 is this master, never used
        for (std::size_t i = 0; i < frame.tiles().size(); ++i) queue_.push_back(int(i));
        image_.width = frame.imageWidth();
        image_.height = frame.imageHeight();
        image_.rgb.assign(std::size_t(image_.width) * image_.height * 3, 0.0f);
    }

    MasterResult run() {
        const auto start = Clock::now();
        for (auto& w : workers_) w.lastHeard = w.lastToldToWait = start;
        MasterSignalNote note(int(done_.size()));
        while (tilesDone_ < int(done_.size())) {
            if (liveWorkers() == 0) throw std::runtime_error(failureReport());
            int flag = 0;
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
            if (flag) {
                receive(status);
                note.setTilesDone(tilesDone_);
            }
            dropSilentWorkers();
            tellWaitersToWait();
            if (!flag) std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        bool anyLost = false;
        for (std::size_t rank = 1; rank < workers_.size(); ++rank) anyLost |= workers_[rank].lost;
        for (std::size_t rank = 1; rank < workers_.size(); ++rank)
            if (workers_[rank].alive || workers_[rank].parked)
                sendInt(int(rank), mpi::kStop, anyLost ? mpi::kSkipFinalize : mpi::kFinalize);
        MasterResult result;
        result.finalize = !anyLost;
        RenderOutput& out = result.output;
        out.metadata = frame_.metadata();
        if (tilesDone_ == int(done_.size())) out.raw = frame_.finishImage(splats_.sum(), image_, out.metadata);
        out.image = std::move(image_);
        out.stats.setupSeconds = frame_.setupSeconds();
        out.stats.renderSeconds = std::chrono::duration<double>(Clock::now() - start).count();
        out.stats.cameraRays = counters_.cameraRays;
        out.stats.blockedCameraRays = counters_.blockedCameraRays;
        out.stats.raysTraced = counters_.raysTraced;
        addRenderWarnings(out, frame_);
        return result;
    }

private:
    void receive(const MPI_Status& status) {
        int bytes = 0;
        MPI_Get_count(&status, MPI_BYTE, &bytes);
        std::vector<unsigned char> message(std::size_t(std::max(bytes, 0)));
        MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const int rank = status.MPI_SOURCE;
        WorkerState& w = workers_[std::size_t(rank)];
        w.lastHeard = Clock::now();
        switch (status.MPI_TAG) {
            case mpi::kHello: w.where.assign(message.begin(), message.end()); break;
            case mpi::kHeartbeat: break;
            case mpi::kRequest:
                acceptResult(rank, message);
                if (w.lost) {
                    // Taken as dead earlier: keep what it sent, give it nothing more.
                    sendInt(rank, mpi::kStop, mpi::kSkipFinalize);
                    break;
                }
                w.waiting = true;
                handOutTiles();
                break;
            case mpi::kFailed:
                if (w.alive) fail(rank, "reported an error: " + std::string(message.begin(), message.end()));
                w.parked = true;
                break;
            default: throw std::runtime_error("rank " + std::to_string(rank) + " sent an unknown message tag " + std::to_string(status.MPI_TAG));
        }
    }

    void acceptResult(int rank, const std::vector<unsigned char>& message) {
        mpi::TileResultHeader head;
        if (message.size() < sizeof head) throw std::runtime_error("rank " + std::to_string(rank) + " sent a truncated tile");
        std::memcpy(&head, message.data(), sizeof head);
        WorkerState& w = workers_[std::size_t(rank)];
        if (head.tileIndex < 0) return;
        if (head.tileIndex >= int(done_.size())) throw std::runtime_error("rank " + std::to_string(rank) + " sent an unknown tile");
        const PixelRect& tile = frame_.tiles()[std::size_t(head.tileIndex)];
        const std::size_t width = std::size_t(tile.x1 - tile.x0), height = std::size_t(tile.y1 - tile.y0);
        const std::size_t pixelBytes = sizeof(float) * 3 * width * height;
        const PixelRect splatBox{head.splatBox[0], head.splatBox[1], head.splatBox[2], head.splatBox[3]};
        const std::size_t splatFloats = splatBox.x1 > splatBox.x0 && splatBox.y1 > splatBox.y0
                                            ? std::size_t(splatBox.x1 - splatBox.x0) * std::size_t(splatBox.y1 - splatBox.y0) * 3
                                            : 0;
        if (message.size() != sizeof head + pixelBytes + sizeof(float) * splatFloats)
            throw std::runtime_error("rank " + std::to_string(rank) + " sent a tile of the wrong size");
        if (w.tile == head.tileIndex) w.tile = -1;
        if (done_[std::size_t(head.tileIndex)]) return;  // re-queued and already done by another worker
        const float* pixels = reinterpret_cast<const float*>(message.data() + sizeof head);
        const PixelRect& area = frame_.area();
        for (std::size_t row = 0; row < height; ++row)
            std::memcpy(&image_.rgb[((std::size_t(tile.y0 - area.y0) + row) * image_.width + std::size_t(tile.x0 - area.x0)) * 3],
                        pixels + row * width * 3, sizeof(float) * 3 * width);
        std::vector<float> splats(splatFloats);
        std::memcpy(splats.data(), message.data() + sizeof head + pixelBytes, sizeof(float) * splatFloats);
        splats_.tileDone(std::size_t(head.tileIndex),
                         SplatBuffer::fromParts(splatFloats > 0 ? splatBox : PixelRect{}, std::move(splats)));
        done_[std::size_t(head.tileIndex)] = true;
        ++tilesDone_;
        ++w.tilesDone;
        counters_ += TileCounters{head.cameraRays, head.blockedCameraRays, head.raysTraced};
        if (onTile_)
            onTile_({tile.x0 - area.x0, tile.y0 - area.y0, tile.x1 - area.x0, tile.y1 - area.y0, tilesDone_, int(done_.size())},
                    image_);
    }

    void handOutTiles() {
        for (std::size_t rank = 1; rank < workers_.size() && !queue_.empty(); ++rank) {
            WorkerState& w = workers_[rank];
            if (!w.alive || !w.waiting) continue;
            while (!queue_.empty() && done_[std::size_t(queue_.front())]) queue_.pop_front();
            if (queue_.empty()) break;
            w.tile = queue_.front();
            w.waiting = false;
            queue_.pop_front();
            sendInt(int(rank), mpi::kTile, w.tile);
        }
    }

    void dropSilentWorkers() {
        const auto now = Clock::now();
        for (std::size_t rank = 1; rank < workers_.size(); ++rank) {
            const double silent = std::chrono::duration<double>(now - workers_[rank].lastHeard).count();
            WorkerState& w = workers_[rank];
            if (w.alive && silent > options_.workerTimeoutSeconds) {
                w.lost = true;
                fail(int(rank), "sent nothing for " + std::to_string(int(silent)) + " s (died or hung)");
                if (w.waiting) sendInt(int(rank), mpi::kStop, mpi::kSkipFinalize);  // should it still be there
            }
        }
    }

    // Workers without a tile (the queue is empty, or they reported an error) hear from rank 0
    // several times per timeout, so that they do not take it for dead.
    void tellWaitersToWait() {
        const auto now = Clock::now();
        const auto every = std::chrono::duration<double>(options_.workerTimeoutSeconds / 4);
        for (std::size_t rank = 1; rank < workers_.size(); ++rank) {
            WorkerState& w = workers_[rank];
            if (((w.alive && w.waiting) || w.parked) && now - w.lastToldToWait > every) {
                sendInt(int(rank), mpi::kWait, 0);
                w.lastToldToWait = now;
            }
        }
    }

    void fail(int rank, const std::string& why) {
        WorkerState& w = workers_[std::size_t(rank)];
        w.alive = false;
        w.failure = why;
        std::string requeued = "no tile in hand";
        if (w.tile >= 0) {
            queue_.push_front(w.tile);
            requeued = "its tile " + std::to_string(w.tile) + " goes back to the queue";
            w.tile = -1;
        }
        std::fprintf(stderr, "lenslab: MPI worker rank %d (%s) %s after %d tile(s); %s; %d of %zu tiles done, %d worker(s) left\n",
                     rank, w.where.c_str(), why.c_str(), w.tilesDone, requeued.c_str(), tilesDone_, done_.size(),
                     liveWorkers());
        handOutTiles();
    }

    int liveWorkers() const {
        int n = 0;
        for (std::size_t rank = 1; rank < workers_.size(); ++rank) n += workers_[rank].alive;
        return n;
    }

    std::string failureReport() const {
        std::string s = "MPI render failed: no worker left";
        for (std::size_t rank = 1; rank < workers_.size(); ++rank)
            s += "; rank " + std::to_string(rank) + " (" + workers_[rank].where + ") " + workers_[rank].failure;
        return s + "; " + std::to_string(tilesDone_) + " of " + std::to_string(done_.size()) +
               " tiles were done; no image was written";
    }

    const PreparedFrame& frame_;
    const MpiRenderOptions& options_;
    const std::function<void(const TileUpdate&, const Image&)>& onTile_;
    std::vector<WorkerState> workers_;
    std::deque<int> queue_;
    std::vector<bool> done_;
    int tilesDone_ = 0;
    TileCounters counters_;
    Image image_;
    SplatImage splats_;
};

}  // namespace

MasterResult runTileMaster(const PreparedFrame& frame, const MpiRenderOptions& options,
                           const std::function<void(const TileUpdate&, const Image&)>& onTile) {
    return TileMaster(frame, options, onTile).run();
}

void stopAllWorkers() {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    for (int rank = 1; rank < size; ++rank) sendInt(rank, mpi::kStop, mpi::kFinalize);
}

}  // namespace lenslab
