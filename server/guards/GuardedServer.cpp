#include "guards/GuardedServer.h"

#include <malloc.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <iostream>

#include "core/SecurityHeaders.h"

namespace lenslab {

namespace {

thread_local GuardedStream* streamOnThisThread = nullptr;
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
    return {limits.stream.maxHeaderBytes, limits.stream.maxBodyWireBytes, limits.stream.headerTimeout,
            limits.idleTimeout, limits.stream.readTimeout, limits.maxWaiting, limits.maxBufferedBytes};
}

// The length of the request line at the start of `head` (all of it when no line end has come).
std::size_t requestLineLength(const std::string& head) {
    const std::size_t end = head.find('\n');
    return end == std::string::npos ? head.size() : end;
}

// An answer written without cpp-httplib, for a request it cannot read at all.
void writeRefusal(int socket, const char* statusLine, const std::string& message) {
    const std::string body = "{\"error\":\"" + message + "\"}";
    std::string reply = std::string("HTTP/1.1 ") + statusLine + "\r\nContent-Type: application/json\r\n";
    for (const auto& [name, value] : securityHeaders()) reply += std::string(name) + ": " + value + "\r\n";
    reply += "Content-Length: " + std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body;
    (void)::send(socket, reply.data(), reply.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
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
          workers_.enqueue([this, c = std::make_shared<WaitingConnection>(std::move(connection))] {
              try {
                  answer(std::move(*c));
              } catch (const std::exception& e) {  // nothing may end a worker thread, and the process with it
                  std::cerr << "lenslab serve: a connection failed: " << e.what() << "\n";
              }
          });
      }) {
    set_socket_options(exclusiveSocketOptions);
    set_idle_interval(std::chrono::duration_cast<std::chrono::seconds>(limits.trimAfterIdle).count());
    // The Keep-Alive header states the limits this class enforces.
    set_keep_alive_timeout(std::chrono::duration_cast<std::chrono::seconds>(limits.idleTimeout).count());
    set_keep_alive_max_count(limits.requestsPerConnection);
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

bool GuardedServer::closesAfterThisRequest() { return closeOnThisThread || violationOnThisThread() != StreamViolation::None; }

void GuardedServer::liftAnswerDeadlineOnThisThread() {
    if (streamOnThisThread) streamOnThisThread->liftAnswerDeadline();
}

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
    if (requestLineLength(connection.pending) > CPPHTTPLIB_REQUEST_URI_MAX_LENGTH) {
        writeRefusal(connection.socket, "414 URI Too Long", "request line too long (at most " +
                                                                std::to_string(CPPHTTPLIB_REQUEST_URI_MAX_LENGTH) + " bytes)");
        closeSocket(connection.socket);
        return;
    }
    GuardedStream stream(connection.socket, limits_.stream, std::move(connection.pending), connection.headDeadline,
                         connection.bodyDeadline);
    streamOnThisThread = &stream;
    closeOnThisThread = false;
    const bool last = connection.served + 1 >= limits_.requestsPerConnection || !is_running();
    bool closed = false;
    // Ranges are applied by the service to complete answers only (ByteRange.h).
    const bool answered = process_request(stream, last, closed, [](httplib::Request& req) { req.ranges.clear(); });
    streamOnThisThread = nullptr;
    if (!answered || closed || last || closeOnThisThread || stream.violation() != StreamViolation::None) {
        closeSocket(connection.socket);
        return;
    }
    connection.pending = stream.leftover();
    connection.bodyDeadline = {};
    ++connection.served;
    waiter_.add(std::move(connection));
}

}  // namespace lenslab
