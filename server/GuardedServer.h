#pragma once
// cpp-httplib's server with its connection loop replaced: every connection is read through a
// GuardedStream (header deadline, header and body budgets), waits between keep-alive requests
// are bounded, the listen backlog is raised from its built-in 5, and the listening socket is
// not shared: without SO_REUSEPORT a second server on the same port fails to bind instead of
// taking every other connection.
#include <httplib.h>

#include <chrono>
#include <cstddef>

#include "GuardedStream.h"

namespace lenslab {

struct ConnectionLimits {
    StreamLimits stream;
    std::chrono::milliseconds idleTimeout{2000};  // keep-alive wait for the next request
    std::size_t requestsPerConnection = 100;
    int listenBacklog = 128;
};

class GuardedServer : public httplib::Server {
public:
    explicit GuardedServer(const ConnectionLimits& limits);

    // Binds like bind_to_port / bind_to_any_port (port 0), then sets the backlog. Returns the port,
    // or -1 when the address cannot be bound.
    int bindTo(const std::string& host, int port);

    // The limit the request being answered on this thread broke, if any (for its error answer).
    static StreamViolation violationOnThisThread();

private:
    bool process_and_close_socket(socket_t socket) override;

    ConnectionLimits limits_;
};

}  // namespace lenslab
