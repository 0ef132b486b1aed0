#pragma once
// Everything `lenslab serve` can be told: where it listens, where its folders are, its limits.
#include <cstddef>
#include <string>

namespace lenslab {

struct RenderLimits {
    int maxWidth = 1920, maxHeight = 1920;
    int maxSpp = 1024;
    int maxQueued = 8;           // jobs waiting (not counting the running ones)
    int concurrentRenders = 1;   // jobs rendering at once
    int threadsPerRender = 0;    // 0: all cores
};

struct ServiceConfig {
    std::string host = "127.0.0.1";
    int port = 8080;             // 0: any free port (printed at start)
    std::string dataDir;         // uploads, jobs, database, report
    std::string lensesDir;       // bundled lens tables (read-only)
    std::string scenesDir;       // bundled scenes (read-only)
    std::string webDir;          // the static web page
    std::string reportDir;       // served at /report/
    std::string accessLogPath;   // empty: standard output
    RenderLimits limits;
    std::size_t maxBodyBytes = 1 << 20;
    int maxUploadedLenses = 500;
    std::size_t diagramCacheBytes = 64u << 20;
    int httpThreads = 32;
    std::string mpiHostfile;     // non-empty: renders run through mpirun over these hosts
    int mpiProcesses = 2;        // mpirun -np (rank 0 schedules, the others render)
};

}  // namespace lenslab
