#pragma once
// The HTTP front: cpp-httplib behind GuardedServer with the service's limits (workers, header and
// body budgets, timeouts, ranges), the checks on each request's head (framing, encodings, ranges,
// Host, access, CORS; also before "100 Continue"), byte ranges applied to complete answers only,
// every failure answered as JSON {"error": ...}, the access log, and a listening thread.
#include <httplib.h>

#include <string>
#include <thread>

#include "guards/AccessLog.h"
#include "guards/GuardedServer.h"
#include "core/ServiceConfig.h"

namespace lenslab {

class HttpServer {
public:
    HttpServer(const ServiceConfig& config, AccessLog& log);
    ~HttpServer();  // stop()

    httplib::Server& routes() { return server_; }

    // Binds host:port (port 0: any free port), starts serving, returns the bound port.
    // std::runtime_error saying so when the address is taken or cannot be bound.
    int start(const std::string& host, int port);
    void stop();

private:
    GuardedServer server_;
    std::thread listener_;
};

}  // namespace lenslab
