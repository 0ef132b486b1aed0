#pragma once
// Everything `lenslab serve` can be told: where it listens, where its folders are, its limits.
#include <cstddef>
#include <cstdint>
#include <string>

namespace lenslab {

struct RenderLimits {
    int maxWidth = 1920, maxHeight = 1920;
    int maxSpp = 1024;
    int maxQueued = 8;           // jobs waiting (not counting the running ones)
    int concurrentRenders = 1;   // jobs rendering at once
    int threadsPerRender = 0;    // 0: all cores
};

// What one connection and one request may cost before the server answers 4xx and moves on
// (docs/api.md, "Limits").
struct HttpLimits {
    std::size_t maxHeaderBytes = 16 << 10;  // request line and headers together: 431 past it
    std::size_t maxBodyBytes = 1 << 20;     // any transfer encoding: 413 past it
    int maxRanges = 1;                      // byte ranges in one Range header: 416 past it
    int headerTimeoutSeconds = 10;          // the whole request head must arrive within this: 408
    int readTimeoutSeconds = 10;            // a body must arrive within this, in all
    int idleTimeoutSeconds = 2;             // keep-alive wait for the next request
    // A whole answer must be taken within this from its first byte, or the connection is cut (event
    // streams excepted: they last their job's life, in slots of their own). The write timeout is per
    // write: 40 readers taking a 44 MB download at 74 KB/s held every worker for 10 minutes.
    int answerTimeoutSeconds = 300;
    int downloadsPerClient = 4;             // render images sent to one client address at once: 429 past it
    int requestsPerConnection = 100;        // then the connection is closed
    int maxConnections = 512;               // open connections not being answered; the longest waiting go first
    int listenBacklog = 128;
};

// The heavy-work pool (jobs/WorkPool.h): analyses, previews, diagrams drawn, uploads parsed, reports.
struct WorkLimits {
    int threads = 0;    // running at once; 0: one per core
    int perClient = 4;  // requests of one client address waiting on heavy work at most
};

// Who may do what (docs/api.md, "Access"). The token is required for every request that writes or
// spends CPU (any method but GET/HEAD/OPTIONS, and the reads computed in the heavy-work pool:
// analyses and diagrams) when it is set, and for reads too with privateReads.
struct AccessPolicy {
    std::string tokenFile;               // where the token is kept (created on first start)
    std::string token;                   // empty: no token asked for (loopback, or --no-auth)
    bool privateReads = false;
    std::string allowedOrigins;          // comma-separated origins besides the server's own
    std::string allowedHosts;            // comma-separated names the server answers to besides addresses
};

// How long finished renders are kept (docs/api.md, "Retention"): the oldest go first.
struct RetentionPolicy {
    double keepDays = 30;                   // 0: no age limit
    std::uintmax_t keepBytes = 2ull << 30;  // finished renders' files together; 0: no size limit
    int keepCount = 10000;                  // finished renders' records; 0: no count limit
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
    HttpLimits http;
    RetentionPolicy retention;
    AccessPolicy access;
    int maxUploadedLenses = 500;
    std::uintmax_t maxDataBytes = 10ull << 30;  // data folder at most; then uploads and renders get 507 (0: no quota)
    bool maxDataBytesGiven = false;             // false: the default, lowered to what the disk holds
    std::size_t diagramCacheBytes = 64u << 20;
    std::size_t analysisCacheBytes = 64u << 20;  // analyses and previews as JSON
    int httpThreads = 32;
    WorkLimits work;                             // requests waiting on it: at most a quarter of the HTTP threads
    std::string mpiHostfile;     // non-empty: renders run through mpirun over these hosts
    int mpiProcesses = 2;        // mpirun -np (rank 0 schedules, the others render)
};

}  // namespace lenslab
