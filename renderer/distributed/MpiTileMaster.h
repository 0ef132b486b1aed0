#pragma once
// Rank 0: a work queue of tile indices served to the workers (ranks 1..size-1) on request, the
// returned pixels written into the image. A worker that fails or falls silent loses its tile to
// the others; when no worker is left the render fails.
#include <functional>

#include "MpiRender.h"
#include "render/PreparedFrame.h"

namespace lenslab {

struct MasterResult {
    RenderOutput output;
    bool finalize = true;  // false once a worker was lost: MPI_Finalize could wait for it forever
};

// Returns once every tile has arrived and every worker still running has been told to stop. Throws
// std::runtime_error naming the failed workers and the tiles done when no worker is left (the
// caller then aborts the job).
MasterResult runTileMaster(const PreparedFrame& frame, const MpiRenderOptions& options,
                           const std::function<void(const TileUpdate&, const Image&)>& onTile);

// Tells every worker to stop (rank 0 failed before its loop).
void stopAllWorkers();

}  // namespace lenslab
