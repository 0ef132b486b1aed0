// Round-trip time of the tile protocol's two message shapes between rank 0 and rank 1: a 4-byte
// tile index and a tile result (12 * side^2 bytes of RGB floats plus a 32-byte header).
// Run: mpirun --allow-run-as-root -np 2 build/bench/mpi/tile_message_latency
#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    constexpr int kRounds = 2000;
    if (rank == 0) std::printf("| message | bytes | round trip (us) | throughput (GB/s) |\n|---|---|---|---|\n");
    for (int side : {0, 8, 16, 32, 64, 128}) {
        const int bytes = side == 0 ? 4 : 32 + 12 * side * side;
        std::vector<char> buffer(static_cast<std::size_t>(bytes));
        MPI_Barrier(MPI_COMM_WORLD);
        const double start = MPI_Wtime();
        for (int i = 0; i < kRounds; ++i) {
            if (rank == 0) {
                MPI_Send(buffer.data(), bytes, MPI_BYTE, 1, 0, MPI_COMM_WORLD);
                MPI_Recv(buffer.data(), bytes, MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            } else if (rank == 1) {
                MPI_Recv(buffer.data(), bytes, MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Send(buffer.data(), bytes, MPI_BYTE, 0, 0, MPI_COMM_WORLD);
            }
        }
        const double roundTrip = (MPI_Wtime() - start) / kRounds;
        if (rank == 0)
            std::printf("| %s | %d | %.1f | %.2f |\n",
                        side == 0 ? "tile index" : ("tile result " + std::to_string(side) + "x" + std::to_string(side)).c_str(),
                        bytes, roundTrip * 1e6, 2.0 * bytes / roundTrip * 1e-9);
    }
    MPI_Finalize();
    return 0;
}
