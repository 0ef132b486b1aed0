#include "GuardedServer.h"

#include <malloc.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace lenslab {

namespace {

thread_local const GuardedStream* streamOnThisThread = nullptr;
thread_local bool closeOnThisThread = false;

void exclusiveSocketOptions(socket_t socket) {
    const int yes = 1;
    ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);  // restart while old connections linger
}

// Runs each task at once on the listening thread: the task only hands the new connection to the
// HeadWaiter, so accepting never waits for a worker.
class HandOver : public httplib::TaskQueue {
public:
    void enqueue(std::function<void()> task) override { task(); }
    void shutdown() override {}
    // glibc keeps memory freed by the worker threads in their arenas; after a burst of diagram
    // drawing that stayed resident for good. Given back when no connection came for a while.
    void on_idle() override { ::malloc_trim(0); }
};

HeadWaiter::Limits waiterLimits(const ConnectionLimits& limits) {
    return {limits.stream.maxHeaderBytes, limits.stream.headerTimeout, limits.idleTimeout, limits.maxWaiting};
}

void closeSocket(int socket) {
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
}

}  // namespace

GuardedServer::GuardedServer(const ConnectionLimits& limits)
    : limits_(limits),
      workers_(limits.workers),
      waiter_(waiterLimits(limits), [this](WaitingConnection connection) {
          workers_.enqueue([this, c = std::make_shared<WaitingConnection>(std::move(connection))] { answer(std::move(*c)); });
      }) {
    set_socket_options(exclusiveSocketOptions);
    set_idle_interval(std::chrono::duration_cast<std::chrono::seconds>(limits.trimAfterIdle).count());
    new_task_queue = [] { return new HandOver; };
}

GuardedServer::~GuardedServer() { closeConnections(); }

int GuardedServer::bindTo(const std::string& host, int port) {
    const int bound = port == 0 ? bind_to_any_port(host) : (bind_to_port(host, port) ? port : -1);
    if (bound <= 0) return -1;
    ::listen(svr_sock_, limits_.listenBacklog);  // on a listening socket this only changes the backlog
    return bound;
}

void GuardedServer::closeConnections() {
    // Called on stop and again on destruction: the worker pool joins its threads only once.
    if (closed_.exchange(true)) return;
    waiter_.stop();
    workers_.shutdown();
}

void GuardedServer::closeAfterThisRequest() { closeOnThisThread = true; }

StreamViolation GuardedServer::violationOnThisThread() {
    return streamOnThisThread ? streamOnThisThread->violation() : StreamViolation::None;
}

bool GuardedServer::process_and_close_socket(socket_t socket) {
    const int yes = 1;
    ::setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    WaitingConnection connection;
    connection.socket = socket;
    waiter_.add(std::move(connection));
    return true;
}

void GuardedServer::answer(WaitingConnection connection) {
    GuardedStream stream(connection.socket, limits_.stream, std::move(connection.pending), connection.headDeadline);
    streamOnThisThread = &stream;
    closeOnThisThread = false;
    const bool last = connection.served + 1 >= limits_.requestsPerConnection || !is_running();
    bool closed = false;
    const bool answered = process_request(stream, last, closed, [this](httplib::Request& req) {
        // Too many ranges: the request is refused (416) before routing, and the refusal itself must
        // not be cut into those ranges (cpp-httplib applies them to every answer, errors too).
        if (req.ranges.size() > limits_.maxRanges) req.ranges.clear();
    });
    streamOnThisThread = nullptr;
    if (!answered || closed || last || closeOnThisThread || stream.violation() != StreamViolation::None) {
        closeSocket(connection.socket);
        return;
    }
    connection.pending = stream.leftover();
    ++connection.served;
    waiter_.add(std::move(connection));
}

}  // namespace lenslab
