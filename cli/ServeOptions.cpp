#include "ServeOptions.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "guards/AccessControl.h"
#include "ArgParser.h"

#ifndef LENSLAB_SOURCE_DIR
#error "LENSLAB_SOURCE_DIR must be defined by the build"
#endif

namespace lenslab {

namespace fs = std::filesystem;

std::string defaultDataDir() {
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return (fs::path(xdg) / "lenslab").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".local" / "share" / "lenslab").string();
    return "data";
}

namespace {

int boundedInteger(const ArgParser& p, const std::string& name, int fallback, long min, long max) {
    const auto value = p.integer(name);
    if (!value) return fallback;
    if (*value < min || *value > max)
        throw UsageError("serve: " + name + " must lie between " + std::to_string(min) + " and " + std::to_string(max));
    return static_cast<int>(*value);
}

double boundedNumber(const ArgParser& p, const std::string& name, double fallback, double min, double max) {
    const auto value = p.number(name);
    if (!value) return fallback;
    if (!(*value >= min && *value <= max))
        throw UsageError("serve: " + name + " must lie between " + std::to_string(min) + " and " + std::to_string(max));
    return *value;
}

}  // namespace

std::optional<ServiceConfig> parseServeOptions(const std::vector<std::string>& args) {
    const std::string source = LENSLAB_SOURCE_DIR;
    ArgParser p("serve", "[--host 127.0.0.1] [--port 8080] [--data DIR] [options]",
                "Runs the lenslab HTTP service: the REST API (docs/api.md) and the web page at /.\n"
                "Uploaded lenses, render jobs and their images live in the data folder and survive restarts.");
    p.option("--host", "ADDR", "address to listen on (default 127.0.0.1, loopback only)");
    p.option("--port", "N", "port (default 8080; 0 picks a free one)");
    p.option("--data", "DIR", "uploads, jobs, database (default " + defaultDataDir() + ")");
    p.option("--lenses", "DIR", "bundled lens tables (default " + source + "/lenses)");
    p.option("--scenes", "DIR", "bundled scenes (default " + source + "/scenes)");
    p.option("--web", "DIR", "the web page (default " + source + "/web)");
    p.option("--report", "DIR", "the report served at /report/ (default DATA/report)");
    p.option("--access-log", "FILE", "JSON-lines access log (default: standard output)");
    p.option("--renders", "N", "renders running at once (default 1)");
    p.option("--max-queue", "N", "renders waiting at most (default 8)");
    p.option("--max-width", "PX", "largest render width (default 1920)");
    p.option("--max-height", "PX", "largest render height (default 1920)");
    p.option("--max-spp", "N", "most samples per pixel (default 1024)");
    p.option("--render-threads", "N", "threads per render (default 0: all cores)");
    p.option("--max-body", "BYTES", "largest request body, any transfer encoding (default 1048576)");
    p.option("--max-header-bytes", "BYTES", "request line and headers together at most (default 16384)");
    p.option("--max-ranges", "N", "byte ranges in one Range header at most (default 1)");
    p.option("--header-timeout", "S", "seconds a request's whole head may take to arrive (default 10)");
    p.option("--read-timeout", "S", "longest silence inside a request body, seconds (default 10)");
    p.option("--idle-timeout", "S", "keep-alive wait for the next request, seconds (default 2)");
    p.option("--answer-timeout", "S", "seconds a whole answer may take to be sent, from its first byte; then the "
             "connection is cut (default 300; event streams excepted)");
    p.option("--keep-alive-requests", "N", "requests per connection before it is closed (default 100)");
    p.option("--max-connections", "N", "connections waiting for a request at most; the longest waiting are dropped (default 512)");
    p.option("--http-threads", "N", "requests answered at once (default 32)");
    p.option("--downloads-per-client", "N", "render images sent to one client address at once at most; more get 429 "
             "(default 4)");
    p.option("--work-threads", "N", "heavy work (analyses, previews, diagrams, uploads, reports) running at once "
             "(default 0: one per core)");
    p.option("--work-per-client", "N", "requests of one client address waiting on heavy work at most; more get 429 "
             "(default 4)");
    p.option("--keep-days", "D", "finished renders are deleted after D days (default 30; 0: no age limit)");
    p.option("--keep-gb", "GB", "finished renders' files kept at most, oldest deleted first (default 2; 0: no limit)");
    p.option("--keep-renders", "N", "finished renders kept at most, oldest deleted first (default 10000; 0: no limit)");
    p.option("--max-data-gb", "GB", "data folder at most: past it uploads and renders are refused with 507 "
             "(default 10; 0: no quota)");
    p.option("--token-file", "FILE", "API token for requests that write or spend CPU; made on first start "
             "(needed beyond loopback)");
    p.flag("--no-auth", "serve beyond loopback without a token (anyone reaching the port may write)");
    p.flag("--private-reads", "with a token: reads need it too");
    p.option("--allow-origin", "ORIGINS", "comma-separated origins whose pages may call the API (default: none)");
    p.option("--allow-host", "NAMES", "comma-separated host names the server answers to besides its addresses and "
             "localhost (others get 421: DNS rebinding)");
    p.option("--mpi-hostfile", "FILE", "run each render through mpirun over these hosts (docs/scaling.md)");
    p.option("--mpi-np", "N", "with --mpi-hostfile: MPI processes per render (default 2)");
    if (!p.parse(args)) {
        std::cout << p.help();
        return std::nullopt;
    }
    ServiceConfig c;
    c.host = p.get("--host", c.host);
    c.port = boundedInteger(p, "--port", c.port, 0, 65535);
    c.dataDir = p.get("--data", defaultDataDir());
    c.lensesDir = p.get("--lenses", source + "/lenses");
    c.scenesDir = p.get("--scenes", source + "/scenes");
    c.webDir = p.get("--web", source + "/web");
    c.reportDir = p.get("--report", (fs::path(c.dataDir) / "report").string());
    c.accessLogPath = p.get("--access-log");
    c.limits.concurrentRenders = boundedInteger(p, "--renders", c.limits.concurrentRenders, 1, 16);
    c.limits.maxQueued = boundedInteger(p, "--max-queue", c.limits.maxQueued, 0, 1000);
    c.limits.maxWidth = boundedInteger(p, "--max-width", c.limits.maxWidth, 8, 16384);
    c.limits.maxHeight = boundedInteger(p, "--max-height", c.limits.maxHeight, 8, 16384);
    c.limits.maxSpp = boundedInteger(p, "--max-spp", c.limits.maxSpp, 1, 1 << 16);
    c.limits.threadsPerRender = boundedInteger(p, "--render-threads", c.limits.threadsPerRender, 0, 256);
    c.http.maxBodyBytes = static_cast<std::size_t>(boundedInteger(p, "--max-body", static_cast<int>(c.http.maxBodyBytes), 1024, 64 << 20));
    c.http.maxHeaderBytes = static_cast<std::size_t>(boundedInteger(p, "--max-header-bytes", static_cast<int>(c.http.maxHeaderBytes), 1024, 1 << 20));
    c.http.maxRanges = boundedInteger(p, "--max-ranges", c.http.maxRanges, 1, 16);
    c.http.headerTimeoutSeconds = boundedInteger(p, "--header-timeout", c.http.headerTimeoutSeconds, 1, 600);
    c.http.readTimeoutSeconds = boundedInteger(p, "--read-timeout", c.http.readTimeoutSeconds, 1, 600);
    c.http.idleTimeoutSeconds = boundedInteger(p, "--idle-timeout", c.http.idleTimeoutSeconds, 1, 600);
    c.http.answerTimeoutSeconds = boundedInteger(p, "--answer-timeout", c.http.answerTimeoutSeconds, 1, 86400);
    c.http.downloadsPerClient = boundedInteger(p, "--downloads-per-client", c.http.downloadsPerClient, 1, 256);
    c.http.requestsPerConnection = boundedInteger(p, "--keep-alive-requests", c.http.requestsPerConnection, 1, 100000);
    c.http.maxConnections = boundedInteger(p, "--max-connections", c.http.maxConnections, 4, 100000);
    c.httpThreads = boundedInteger(p, "--http-threads", c.httpThreads, 2, 256);
    c.work.threads = boundedInteger(p, "--work-threads", c.work.threads, 0, 256);
    c.work.perClient = boundedInteger(p, "--work-per-client", c.work.perClient, 1, 256);
    c.retention.keepDays = boundedNumber(p, "--keep-days", c.retention.keepDays, 0, 36500);
    c.retention.keepBytes = static_cast<std::uintmax_t>(
        boundedNumber(p, "--keep-gb", static_cast<double>(c.retention.keepBytes) / (1 << 30), 0, 1e6) * (1 << 30));
    c.retention.keepCount = boundedInteger(p, "--keep-renders", c.retention.keepCount, 0, 100000000);
    c.maxDataBytes = static_cast<std::uintmax_t>(
        boundedNumber(p, "--max-data-gb", static_cast<double>(c.maxDataBytes) / (1 << 30), 0, 1e6) * (1 << 30));
    c.maxDataBytesGiven = p.has("--max-data-gb");
    c.access.tokenFile = p.get("--token-file");
    c.access.privateReads = p.has("--private-reads");
    c.access.allowedOrigins = p.get("--allow-origin");
    c.access.allowedHosts = p.get("--allow-host");
    if (p.has("--no-auth") && !c.access.tokenFile.empty())
        throw UsageError("serve: --no-auth and --token-file contradict each other");
    if (c.access.privateReads && c.access.tokenFile.empty())
        throw UsageError("serve: --private-reads needs --token-file");
    if (!isLoopbackHost(c.host) && c.access.tokenFile.empty() && !p.has("--no-auth"))
        throw UsageError("serve: listening on " + c.host + " lets other hosts reach the service; give "
                         "--token-file FILE (a token is made there on first start) or, to allow anyone, --no-auth");
    c.mpiHostfile = p.get("--mpi-hostfile");
    c.mpiProcesses = boundedInteger(p, "--mpi-np", c.mpiProcesses, 1, 100000);
    if (!c.mpiHostfile.empty() && !fs::is_regular_file(c.mpiHostfile))
        throw UsageError("serve: --mpi-hostfile '" + c.mpiHostfile + "' is not a file");
    if (!c.mpiHostfile.empty()) c.mpiHostfile = fs::absolute(c.mpiHostfile).string();
    return c;
}

}  // namespace lenslab
