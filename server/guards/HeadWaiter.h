#pragma once
// Connections waiting for a request, watched by one thread with poll(), so that no worker thread
// is tied up by a client that has not finished sending one: a worker gets a connection only once
// its request is whole, head and body (or too large, or late: the worker then answers 431 or 408,
// or ends a body that did not come within the read timeout at once).
// Kept-alive connections come back here between requests and are closed after the idle timeout.
// Past maxWaiting connections, or maxBufferedBytes received and not yet handed on (bodies wait
// here too), the ones waiting longest are dropped first: slow clients go before a new client
// whose request is on its way.
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lenslab {

struct WaitingConnection {
    int socket = -1;
    std::string pending;  // bytes of the next request received so far
    std::size_t served = 0;  // requests answered on it before
    std::chrono::steady_clock::time_point headDeadline;  // set when its first byte arrives
    std::chrono::steady_clock::time_point bodyDeadline;  // set when its head is complete and its body is not
};

class HeadWaiter {
public:
    using Ready = std::function<void(WaitingConnection)>;
    struct Limits {
        std::size_t maxHeaderBytes, maxBodyBytes;
        std::chrono::milliseconds headerTimeout, idleTimeout, readTimeout;
        std::size_t maxWaiting;
        std::size_t maxBufferedBytes;
    };
    HeadWaiter(const Limits& limits, Ready ready);
    ~HeadWaiter();  // stop()

    // Watches a connection: a new one (served 0) or one back after a request.
    void add(WaitingConnection connection);
    // Ends the thread and closes every connection still waiting. Idempotent.
    void stop();

private:
    struct Entry {
        WaitingConnection connection;
        std::chrono::steady_clock::time_point since;  // when it began waiting
        std::chrono::steady_clock::time_point idleDeadline;
        bool started = false;  // its first byte has come: the head deadline runs
        bool headDone = false;  // its head has come: the body deadline runs
    };
    // Hands the entry on when its request is whole; else notes where it stands. True when handed on.
    bool handOnIfWhole(Entry& entry);
    void run();
    // Reads what arrived; true when the entry is done waiting (handed on or closed).
    bool receive(Entry& entry);
    void dropLongestWaiting(std::vector<Entry>& waiting) const;

    Limits limits_;
    Ready ready_;
    int wakeRead_ = -1, wakeWrite_ = -1;
    std::mutex mutex_;
    std::vector<Entry> incoming_;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace lenslab
