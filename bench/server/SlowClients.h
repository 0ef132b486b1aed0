#pragma once
// Slowloris clients for the load benchmark: connections that send a request head one header line
// at a time, one line a second, and connect again whenever the server closes them, so the server
// answers its ordinary clients with these present all along. Loopback only.
#include <atomic>
#include <thread>

namespace lenslab::bench {

class SlowClients {
public:
    SlowClients(int port, int connections);
    ~SlowClients();  // stops and closes them
    SlowClients(const SlowClients&) = delete;
    SlowClients& operator=(const SlowClients&) = delete;

    long reconnects() const { return reconnects_; }  // how often the server cut one off

private:
    std::atomic<bool> stop_{false};
    std::atomic<long> reconnects_{0};
    std::thread thread_;
};

}  // namespace lenslab::bench
