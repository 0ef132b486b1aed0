#pragma once
// A `lenslab serve` child process on loopback with its own temporary data folder, for the load
// benchmarks; and the percentile the tables report.
#include <sys/types.h>

#include <string>
#include <vector>

namespace lenslab::bench {

struct ServerUnderTest {
    pid_t pid = -1;
    int port = 0;
    std::string folder;
};

// Starts `binary serve --port 0` with `extra` flags and waits for its "listening" line.
ServerUnderTest startServer(const std::string& binary, const std::vector<std::string>& extra);
// SIGTERM, wait, and remove the data folder.
void stopServer(const ServerUnderTest& server);
// Resident memory of the process in MiB (VmRSS), 0 when it cannot be read.
double residentMiB(pid_t pid);
// The p-quantile (0..1) of v, nearest rank.
double percentile(std::vector<double> v, double p);

}  // namespace lenslab::bench
