// Roles in the job: rank 0 masters, the others work; a job of one process renders locally.
#include "MpiRender.h"

#include <mpi.h>
#include <sched.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <thread>

#include "MpiTileMaster.h"
#include "MpiTileWorker.h"
#include "render/PreparedFrame.h"

namespace lenslab {

namespace {

// MPI_Init_thread / MPI_Finalize around the render, with errors returned instead of aborting.
class MpiSession {
public:
    MpiSession() {
        int provided = 0;
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
        if (provided < MPI_THREAD_FUNNELED) {
            std::cerr << "lenslab: this MPI library does not allow threads beside MPI calls\n";
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
    }
    ~MpiSession() {
        if (finalize_) MPI_Finalize();
    }
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    // After a rank died (see mpi::StopKind): leave without MPI_Finalize.
    void skipFinalize() { finalize_ = false; }

private:
    bool finalize_ = true;
};

// The cores this process may run on (mpirun binds ranks to cores or sockets unless --bind-to none).
int usableCores() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

// Unless the user chose: a rank that mpirun bound to some cores uses those; an unbound one shares
// the node's cores with the other workers on it (rank 0 only schedules, so it takes none).
int workerThreads(int requested) {
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int onNode = 1, rank = 0, mastersHere = 0;
    MPI_Comm_size(node, &onNode);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const int isMaster = rank == 0;
    MPI_Allreduce(&isMaster, &mastersHere, 1, MPI_INT, MPI_SUM, node);
    MPI_Comm_free(&node);
    if (requested > 0) return requested;
    const int cores = usableCores();
    if (cores < int(std::thread::hardware_concurrency())) return cores;
    return std::max(1, cores / std::max(1, onNode - mastersHere));
}

}  // namespace

bool mpiAvailable() { return true; }

std::optional<RenderOutput> renderSceneOverMpi(const RenderSettings& settings, const MpiRenderOptions& options,
                                               const std::function<void(const TileUpdate&, const Image&)>& onTile) {
    if (!(options.workerTimeoutSeconds > 0)) throw std::invalid_argument("the MPI worker timeout must be positive");
    MpiSession session;
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    RenderSettings local = settings;
    local.threads = workerThreads(settings.threads);  // collective: every rank takes part
    if (size == 1) return renderScene(settings, onTile);
    if (rank != 0) {
        if (!runTileWorker(local, options)) session.skipFinalize();
        return std::nullopt;
    }
    local.threads = settings.threads > 0 ? settings.threads : usableCores();  // for rank 0's own setup
    std::unique_ptr<PreparedFrame> frame;
    try {
        frame = std::make_unique<PreparedFrame>(local);
    } catch (...) {
        stopAllWorkers();
        throw;
    }
    try {
        MasterResult result = runTileMaster(*frame, options, onTile);
        if (!result.finalize) session.skipFinalize();
        return std::move(result.output);
    } catch (const std::exception& e) {
        // Workers may be dead or mid-tile: a clean finalize could wait for them forever.
        std::cerr << "lenslab: " << e.what() << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
        throw;
    }
}

}  // namespace lenslab
