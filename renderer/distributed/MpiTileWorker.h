#pragma once
// A worker rank: builds the frame, then renders the tiles rank 0 hands out until told to stop.
#include "MpiRender.h"

namespace lenslab {

// Returns when rank 0 says Stop: true when MPI_Finalize is safe, false once a rank has died. A
// setup or render error is reported to rank 0 (which carries on with the other workers) rather
// than thrown. Aborts the job (MPI_Abort) when rank 0 stops answering.
bool runTileWorker(const RenderSettings& settings, const MpiRenderOptions& options);

}  // namespace lenslab
