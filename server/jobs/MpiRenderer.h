#pragma once
// The JobRenderer for `lenslab serve --mpi-hostfile H --mpi-np N`: each job runs as
// `mpirun --hostfile H -np N lenslab render ... --mpi --progress-json` (this same lenslab binary),
// its tile lines mapped to the job's progress, cancel killing the mpirun process group. The
// scenes, lenses and the data folder must lie at the same paths on every host (a shared
// filesystem); rank 0, the first slot of the hostfile, writes the images into the data folder.
#include <string>

#include "jobs/JobRenderer.h"

namespace lenslab {

struct MpiLaunch {
    std::string mpirun = "mpirun";  // found on PATH unless a path is given
    std::string hostfile;
    int processes = 2;              // rank 0 schedules, the others render
    int threadsPerWorker = 0;       // 0: the node's cores shared among its workers
    std::string scratchDir;         // where the job's images are written before loading
};

class MpiRenderer : public JobRenderer {
public:
    explicit MpiRenderer(MpiLaunch launch);
    RenderedImages render(const RenderJobInput& job, const TileCallback& onTile, const std::atomic<bool>& cancel) override;
    // Tiles arrive as progress only (the pixels stay in the mpirun job until the end): black.
    std::vector<std::uint8_t> encodePreview(const Image& partial) const override;

private:
    MpiLaunch launch_;
    std::string lenslabBinary_;
};

}  // namespace lenslab
