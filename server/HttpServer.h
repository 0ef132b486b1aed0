#pragma once
// The HTTP front: cpp-httplib configured with the service's limits (threads, timeouts, body
// size), every failure answered as JSON {"error": ...}, the access log, and a listening thread.
#include <httplib.h>

#include <string>
#include <thread>

#include "AccessLog.h"
#include "ServiceConfig.h"

namespace lenslab {

class HttpServer {
public:
    HttpServer(const ServiceConfig& config, AccessLog& log);
    ~HttpServer();  // stop()

    httplib::Server& routes() { return server_; }

    // Binds host:port (port 0: any free port), starts serving, returns the bound port.
    // std::runtime_error when the address cannot be bound.
    int start(const std::string& host, int port);
    void stop();

private:
    httplib::Server server_;
    std::thread listener_;
};

}  // namespace lenslab
