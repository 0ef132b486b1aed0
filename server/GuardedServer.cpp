#include "GuardedServer.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace lenslab {

namespace {

thread_local const GuardedStream* streamOnThisThread = nullptr;

void exclusiveSocketOptions(socket_t socket) {
    const int yes = 1;
    ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);  // restart while old connections linger
}

}  // namespace

GuardedServer::GuardedServer(const ConnectionLimits& limits) : limits_(limits) {
    set_socket_options(exclusiveSocketOptions);
}

int GuardedServer::bindTo(const std::string& host, int port) {
    const int bound = port == 0 ? bind_to_any_port(host) : (bind_to_port(host, port) ? port : -1);
    if (bound <= 0) return -1;
    ::listen(svr_sock_, limits_.listenBacklog);  // on a listening socket this only changes the backlog
    return bound;
}

StreamViolation GuardedServer::violationOnThisThread() {
    return streamOnThisThread ? streamOnThisThread->violation() : StreamViolation::None;
}

bool GuardedServer::process_and_close_socket(socket_t socket) {
    const int yes = 1;
    ::setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    GuardedStream stream(socket, limits_.stream);
    streamOnThisThread = &stream;
    bool answered = false;
    for (std::size_t left = limits_.requestsPerConnection; left > 0 && is_running(); --left) {
        if (!stream.waitForRequest(limits_.idleTimeout)) break;
        stream.beginRequest();
        bool closed = false;
        answered = process_request(stream, left == 1 || !is_running(), closed, nullptr);
        if (!answered || closed || stream.violation() != StreamViolation::None) break;
    }
    streamOnThisThread = nullptr;
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
    return answered;
}

}  // namespace lenslab
