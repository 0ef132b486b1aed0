#pragma once
// cpp-httplib's server with its connection handling replaced. cpp-httplib 0.11.4 gives each
// connection a worker thread from accept to close, so clients that send slowly, or keep a
// connection open, hold workers; 33 slow connections stopped a 32-thread server. Here:
// - accepted connections wait in a HeadWaiter (one thread, poll) until a request head is complete;
//   only then does a worker read the request, through a GuardedStream (header deadline, header
//   and body budgets), answer it, and hand the connection back to wait for the next request;
// - byte ranges are left to the service (cpp-httplib would cut error answers and event streams);
// - a request line too long to read is answered 414 here (cpp-httplib would close silently);
// - the listen backlog is raised from its built-in 5;
// - the listening socket is not shared: without SO_REUSEPORT a second server on the same port
//   fails to bind instead of taking every other connection.
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>

#include "guards/GuardedStream.h"
#include "guards/HeadWaiter.h"

namespace lenslab {

struct ConnectionLimits {
    StreamLimits stream;
    std::chrono::milliseconds idleTimeout{2000};  // keep-alive wait for the next request
    std::size_t requestsPerConnection = 100;
    std::size_t workers = 32;                     // requests answered at once
    std::size_t maxWaiting = 512;                 // connections between requests or in their head
    std::size_t maxBufferedBytes = 64 << 20;      // requests received by them, not yet answered
    int listenBacklog = 128;
    std::chrono::seconds trimAfterIdle{10};       // no new connection this long: free memory is returned
};

class GuardedServer : public httplib::Server {
public:
    explicit GuardedServer(const ConnectionLimits& limits);
    ~GuardedServer() override;  // closeConnections()

    // Binds like bind_to_port / bind_to_any_port (port 0), then sets the backlog. Returns the port,
    // or -1 when the address cannot be bound.
    int bindTo(const std::string& host, int port);
    // After stop(): lets the workers finish the requests they are answering and closes every
    // connection. Idempotent.
    void closeConnections();

    // The limit the request being answered on this thread broke, if any (for its error answer).
    static StreamViolation violationOnThisThread();
    // Closes the connection once the request being answered on this thread has its answer.
    static void closeAfterThisRequest();
    // Whether it will be closed (asked for, or a limit broken): its answer says Connection: close.
    static bool closesAfterThisRequest();
    // The answer to the request being answered on this thread has no deadline (an event stream).
    static void liftAnswerDeadlineOnThisThread();

private:
    bool process_and_close_socket(socket_t socket) override;  // on the listening thread: hands it on
    void answer(WaitingConnection connection);                // on a worker: one request

    ConnectionLimits limits_;
    httplib::ThreadPool workers_;
    std::atomic<bool> closed_{false};
    HeadWaiter waiter_;
};

}  // namespace lenslab
