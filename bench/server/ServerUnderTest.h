#pragma once
// A `lenslab serve` child process on loopback with its own temporary data folder, for the load
// benchmarks; and the percentile the tables report.
#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace lenslab::bench {

struct ServerUnderTest {
    pid_t pid = -1;
    int port = 0;
    std::string folder;
};

// Starts `binary serve --port 0` with `extra` flags and waits for its "listening" line (10 minutes
// at most); its data folder is `data`, else one of its own under `folder`.
ServerUnderTest startServer(const std::string& binary, const std::vector<std::string>& extra, const std::string& data = "");
// SIGTERM, wait, and remove the data folder.
void stopServer(const ServerUnderTest& server);
// Resident memory of the process in MiB (VmRSS), 0 when it cannot be read.
double residentMiB(pid_t pid);
// The p-quantile (0..1) of v, nearest rank.
double percentile(std::vector<double> v, double p);
// Socket options (httplib's SocketOptions) that make a client's connections come from
// 127.0.0.(2 + index % 250): the server tells clients apart by address, as it would other hosts
// (the heavy-work pool's per-client share).
std::function<void(int)> fromLoopbackAddress(int index);

}  // namespace lenslab::bench
