#pragma once
// The messages between rank 0 (the tile master) and the workers, on MPI_COMM_WORLD.
// Worker -> master: Hello (host and pid, once), Heartbeat (while busy or waiting), Request (asks
// for a tile, carrying the previous tile's result if any), Failed (an error text; the worker then
// waits for Stop). Master -> worker: Tile (a tile index), Stop (a StopKind), or Wait (no tile yet:
// the queue is empty until the last tiles arrive or a lost worker's tile comes back; sent while the
// worker waits, so that it can tell a busy master from a dead one). All ranks run the same binary
// on machines of one architecture, so the result travels as raw bytes.
#include <cstdint>

namespace lenslab::mpi {

enum Tag : int { kHello = 1, kHeartbeat, kRequest, kFailed, kTile = 10, kStop, kWait };

// Once a rank has died, MPI_Finalize can wait for it forever (seen with Open MPI 4.1.4 under
// mpirun --enable-recovery), so then every rank leaves without it; mpirun still exits with 0.
enum StopKind : int { kFinalize = 0, kSkipFinalize = 1 };

// Head of a Request; followed by the tile's RGB floats, row-major, then its splats' RGB floats over
// their box (render/SplatBuffer.h: a spectral frame's wavelengths landing in other pixels; an empty
// box when none), none of either when tileIndex < 0.
struct TileResultHeader {
    std::int32_t tileIndex = -1;
    std::int32_t reserved = 0;
    std::int32_t splatBox[4] = {0, 0, 0, 0};  // x0, y0, x1, y1, full-image pixels
    std::uint64_t cameraRays = 0, blockedCameraRays = 0, raysTraced = 0;
};

}  // namespace lenslab::mpi
