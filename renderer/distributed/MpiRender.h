#pragma once
// Renders one frame with the tiles spread over the processes of an MPI job
// (`mpirun -np N lenslab render SCENE --mpi`). Rank 0 hands out tiles from a work queue and
// assembles the image; every other rank is a worker that renders the tiles it is given. The
// image equals the single-process render with the same settings bit for bit.
#include <functional>
#include <optional>

#include "Render.h"

namespace lenslab {

struct MpiRenderOptions {
    // A worker that sends nothing (no heartbeat, no tile) for this long is taken as dead and its
    // tile goes back to the queue. Workers send a heartbeat several times per timeout.
    double workerTimeoutSeconds = 10;
};

// True when this lenslab was built with Open MPI (LENSLAB_MPI).
bool mpiAvailable();

// Every rank of the job calls this with the same settings; it initialises and finalises MPI.
// Rank 0 returns the image (onTile is called on rank 0 after each tile arrives, with the image so
// far); workers return nullopt. With a single process rank 0 renders locally. Throws what
// renderScene throws for the scene and settings (after telling the workers to stop), and
// std::runtime_error when lenslab was built without MPI. When the job cannot finish (every worker
// failed) rank 0 says why and aborts the job (MPI_Abort). The settings' thread count 0 means: the
// cores mpirun bound the rank to, or, unbound, the node's cores shared among its workers.
std::optional<RenderOutput> renderSceneOverMpi(const RenderSettings& settings, const MpiRenderOptions& options,
                                               const std::function<void(const TileUpdate&, const Image&)>& onTile = {});

}  // namespace lenslab
