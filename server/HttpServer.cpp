#include "HttpServer.h"

#include <chrono>
#include <stdexcept>

#include "HttpError.h"
#include "HttpReply.h"
#include "LensDiagram.h"
#include "LensTable.h"
#include "OpticsError.h"
#include "Render.h"

namespace lenslab {

namespace {

// The answer for an exception a handler let through.
void replyForException(httplib::Response& res, std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const HttpError& e) {
        replyError(res, e.status(), e.what());
    } catch (const LensTableError& e) {
        replyError(res, 400, e.what());
    } catch (const OpticsError& e) {
        replyError(res, 422, e.what());
    } catch (const SceneError& e) {
        replyError(res, 422, e.what());
    } catch (const DiagramError& e) {
        replyError(res, 503, std::string("the diagram could not be drawn: ") + e.what());
    } catch (const std::exception& e) {
        replyError(res, 500, std::string("internal error: ") + e.what());
    } catch (...) {
        replyError(res, 500, "internal error");
    }
}

const char* defaultMessage(int status) {
    switch (status) {
        case 400: return "bad request";
        case 404: return "not found";
        case 405: return "method not allowed";
        case 413: return "request body too large";
        case 414: return "request URI too long";
        case 416: return "range not satisfiable";
        default: return status >= 500 ? "internal error" : "request refused";
    }
}

}  // namespace

HttpServer::HttpServer(const ServiceConfig& config, AccessLog& log) {
    const int threads = config.httpThreads;
    server_.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<std::size_t>(threads)); };
    server_.set_payload_max_length(config.maxBodyBytes);
    // Headers and body go out in separate writes: without this, Nagle's algorithm holds the body
    // back until the client's delayed ACK (about 40 ms per response).
    server_.set_tcp_nodelay(true);
    server_.set_read_timeout(10, 0);
    server_.set_write_timeout(10, 0);
    server_.set_keep_alive_timeout(2);
    server_.set_keep_alive_max_count(1000);
    server_.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Cache-Control", "no-cache"}});
    server_.set_pre_routing_handler([&log](const httplib::Request&, httplib::Response&) {
        log.requestStarted();
        return httplib::Server::HandlerResponse::Unhandled;
    });
    server_.set_logger([&log](const httplib::Request& req, const httplib::Response& res) { log.requestFinished(req, res); });
    server_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
        replyForException(res, error);
    });
    server_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (res.body.empty()) replyError(res, res.status, defaultMessage(res.status));
    });
}

HttpServer::~HttpServer() { stop(); }

int HttpServer::start(const std::string& host, int port) {
    int bound = port;
    if (port == 0) bound = server_.bind_to_any_port(host);
    else if (!server_.bind_to_port(host, port)) bound = -1;
    if (bound <= 0) throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port));
    listener_ = std::thread([this] { server_.listen_after_bind(); });
    for (int waited = 0; !server_.is_running(); ++waited) {
        if (waited > 2000) throw std::runtime_error("the HTTP server did not start listening");
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return bound;
}

void HttpServer::stop() {
    if (!listener_.joinable()) return;
    server_.stop();
    listener_.join();
}

}  // namespace lenslab
