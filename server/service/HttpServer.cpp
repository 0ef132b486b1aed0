#include "service/HttpServer.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <stdexcept>

#include "guards/AccessControl.h"
#include "core/ByteRange.h"
#include "guards/CrossOrigin.h"
#include "guards/HostCheck.h"
#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/SecurityHeaders.h"
#include "LensDiagram.h"
#include "prescription/LensTable.h"
#include "prescription/OpticsError.h"
#include "Render.h"
#include "guards/RequestChecks.h"
#include "guards/ResponseEncoding.h"
#include "storage/StorageError.h"

namespace lenslab {

namespace {

// The answer for an exception a handler let through.
void replyForException(httplib::Response& res, std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const HttpError& e) {
        if (e.retryAfterSeconds() > 0) res.set_header("Retry-After", std::to_string(e.retryAfterSeconds()));
        replyError(res, e.status(), e.what());
    } catch (const StorageError& e) {
        std::cerr << "lenslab serve: " << e.detail() << "\n";
        replyError(res, e.httpStatus(), e.what());
    } catch (const LensTableError& e) {
        replyError(res, 400, e.what());
    } catch (const OpticsError& e) {
        replyError(res, 422, e.what());
    } catch (const SceneError& e) {
        replyError(res, 422, e.what());
    } catch (const DiagramError& e) {
        replyError(res, 503, std::string("the diagram could not be drawn: ") + e.what());
    } catch (const std::exception& e) {
        // The text may name the server's files: it goes to the log, not to the client.
        std::cerr << "lenslab serve: internal error: " << e.what() << "\n";
        replyError(res, 500, "internal error (the server's log has the details)");
    } catch (...) {
        replyError(res, 500, "internal error");
    }
}

ConnectionLimits connectionLimits(const HttpLimits& http, int threads) {
    ConnectionLimits limits;
    limits.stream.maxHeaderBytes = http.maxHeaderBytes;
    limits.stream.maxHeaderLine = std::min<std::size_t>(http.maxHeaderBytes, CPPHTTPLIB_HEADER_MAX_LENGTH);
    // A chunked body's payload is held to the exact limit as it arrives; its framing (size lines,
    // CRLFs) travels with the data, so the wire bytes get a margin. A body with a Content-Length
    // past the limit is refused from its head.
    limits.stream.maxBodyBytes = http.maxBodyBytes;
    limits.stream.maxBodyWireBytes = http.maxBodyBytes + http.maxBodyBytes / 16 + 4096;
    limits.stream.headerTimeout = std::chrono::seconds(http.headerTimeoutSeconds);
    limits.stream.readTimeout = std::chrono::seconds(http.readTimeoutSeconds);
    limits.stream.writeTimeout = std::chrono::seconds(http.readTimeoutSeconds);
    limits.stream.answerTimeout = std::chrono::seconds(http.answerTimeoutSeconds);
    limits.idleTimeout = std::chrono::seconds(http.idleTimeoutSeconds);
    limits.requestsPerConnection = static_cast<std::size_t>(http.requestsPerConnection);
    limits.listenBacklog = http.listenBacklog;
    limits.workers = static_cast<std::size_t>(threads);
    limits.maxWaiting = static_cast<std::size_t>(http.maxConnections);
    limits.maxBufferedBytes = std::max<std::size_t>(limits.maxBufferedBytes, 4 * limits.stream.maxBodyWireBytes);
    return limits;
}

void replyBodyTooLarge(httplib::Response& res, const HttpLimits& http) {
    replyError(res, 413, "request body too large (at most " + std::to_string(http.maxBodyBytes) + " bytes)");
}

// The answer for a request the connection's stream cut off, by the limit it broke.
void replyForViolation(httplib::Response& res, StreamViolation violation, const HttpLimits& http) {
    switch (violation) {
        case StreamViolation::HeaderTooLarge:
            return replyError(res, 431, "request headers too large (at most " + std::to_string(http.maxHeaderBytes) +
                                            " bytes in all, " + std::to_string(CPPHTTPLIB_HEADER_MAX_LENGTH) + " per line)");
        case StreamViolation::BodyTooLarge: return replyBodyTooLarge(res, http);
        case StreamViolation::HeaderTimeout:
            return replyError(res, 408, "the request head did not arrive within " +
                                            std::to_string(http.headerTimeoutSeconds) + " s");
        case StreamViolation::None: break;
    }
}

const char* defaultMessage(int status) {
    switch (status) {
        case 400: return "bad request";
        case 404: return "not found";
        case 405: return "method not allowed";
        case 414: return "request URI too long";
        case 416: return "range not satisfiable";
        default: return status >= 500 ? "internal error" : "request refused";
    }
}

}  // namespace

HttpServer::HttpServer(const ServiceConfig& config, AccessLog& log)
    : server_(connectionLimits(config.http, config.httpThreads)) {
    const HttpLimits http = config.http;
    const AccessPolicy access = config.access;
    const std::string listenHost = config.host;
    server_.set_payload_max_length(http.maxBodyBytes);
    httplib::Headers defaultHeaders = {{"Cache-Control", "no-cache"}};
    for (const auto& [name, value] : securityHeaders()) defaultHeaders.emplace(name, value);
    server_.set_default_headers(defaultHeaders);
    // The checks on a request's head; true when it is answered already (refused, or a CORS preflight).
    const auto answeredByHead = [&log, http, access, listenHost](const httplib::Request& req, httplib::Response& res) {
        log.requestStarted();
        declineBrotli(req);
        auto refusal = refuseRequestHead(req, http);
        if (!refusal) refusal = refuseHost(req, listenHost, access.allowedHosts);
        if (!refusal && allowListedOrigin(req, res, access)) return true;
        if (!refusal) refusal = refuseAccess(req, access);
        if (!refusal) return false;
        if (refusal->status() == 401) res.set_header("WWW-Authenticate", "Bearer");
        replyError(res, refusal->status(), refusal->what());
        GuardedServer::closeAfterThisRequest();  // its body, if any, was not read
        return true;
    };
    server_.set_pre_routing_handler([answeredByHead](const httplib::Request& req, httplib::Response& res) {
        return answeredByHead(req, res) ? httplib::Server::HandlerResponse::Handled
                                        : httplib::Server::HandlerResponse::Unhandled;
    });
    // A client waiting for "100 Continue" hears the refusal instead, before it sends the body.
    server_.set_expect_100_continue_handler([answeredByHead](const httplib::Request& req, httplib::Response& res) {
        return answeredByHead(req, res) ? res.status : 100;
    });
    server_.set_post_routing_handler([](const httplib::Request& req, httplib::Response& res) {
        applyByteRange(req.get_header_value("Range"), res);
        if (!res.has_header("Vary")) res.set_header("Vary", "Accept-Encoding");  // gzip or not, by the request
        if (GuardedServer::closesAfterThisRequest()) {
            res.headers.erase("Keep-Alive");
            res.headers.erase("Connection");
            res.headers.emplace("Connection", "close");
        }
    });
    server_.set_logger([&log](const httplib::Request& req, const httplib::Response& res) { log.requestFinished(req, res); });
    server_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
        replyForException(res, error);
    });
    server_.set_error_handler([http](const httplib::Request&, httplib::Response& res) {
        // An empty body: cpp-httplib itself refused the request, which it could not read (request
        // line, headers, range syntax). Bytes after it cannot be trusted to start a request.
        if (res.body.empty() && (res.status == 400 || res.status == 414 || res.status == 416))
            GuardedServer::closeAfterThisRequest();
        const StreamViolation violation = GuardedServer::violationOnThisThread();
        if (violation != StreamViolation::None) return replyForViolation(res, violation, http);
        if (res.status == 413 && res.body.empty()) return replyBodyTooLarge(res, http);
        if (res.body.empty()) replyError(res, res.status, defaultMessage(res.status));
    });
}

HttpServer::~HttpServer() { stop(); }

int HttpServer::start(const std::string& host, int port) {
    const int bound = server_.bindTo(host, port);
    if (bound <= 0)
        throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) +
                                 ": the port is in use (another lenslab serve?) or the address is not on this host; "
                                 "choose another with --port");
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
    server_.closeConnections();
}

}  // namespace lenslab
