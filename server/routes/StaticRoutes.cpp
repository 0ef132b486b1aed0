// The web page (web/) at "/" and the generated report at "/report/". Only plain files inside those
// folders are served: every path segment must be a safe name, no "..", no hidden files.
#include <filesystem>
#include <map>

#include "core/HttpReply.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

namespace fs = std::filesystem;

// Path segments made of safe characters, none starting with a dot.
const char* kSafeRelativePath = R"(((?:[A-Za-z0-9_-][A-Za-z0-9._-]*/)*(?:[A-Za-z0-9_-][A-Za-z0-9._-]*)?))";

std::string contentType(const fs::path& file) {
    static const std::map<std::string, std::string> kTypes = {
        {".html", "text/html; charset=utf-8"}, {".js", "text/javascript; charset=utf-8"},
        {".css", "text/css; charset=utf-8"},   {".json", "application/json"},
        {".png", "image/png"},                 {".jpg", "image/jpeg"},
        {".svg", "image/svg+xml"},             {".exr", "image/x-exr"},
        {".txt", "text/plain; charset=utf-8"}, {".csv", "text/csv; charset=utf-8"},
        {".md", "text/plain; charset=utf-8"}};
    const auto it = kTypes.find(file.extension().string());
    return it == kTypes.end() ? "application/octet-stream" : it->second;
}

// Serves root/relative (a folder means its index.html); false when there is no such file.
bool serveInside(const std::string& root, std::string relative, httplib::Response& res) {
    if (relative.empty() || relative.back() == '/') relative += "index.html";
    std::error_code ec;
    const fs::path file = fs::path(root) / relative;
    if (!fs::is_regular_file(file, ec)) return false;
    return replyFile(res, file.string(), contentType(file));
}

const char* kNoReportPage =
    "<!doctype html><html><head><meta charset=\"utf-8\"><title>No report yet</title>"
    "<link rel=\"icon\" href=\"data:,\"></head><body style=\"font-family:sans-serif;max-width:40em;margin:3em auto\">"
    "<h1>No report yet</h1><p>The report has not been generated. Build it from the web page, with "
    "<code>curl -X POST http://HOST:PORT/api/report</code>, or run <code>lenslab report -o DATA/report</code> "
    "(DATA is the service's data folder), then reload this page.</p>"
    "<p><a href=\"/\">Back to lenslab</a></p></body></html>";

const char* kNotFoundPage =
    "<!doctype html><html><head><meta charset=\"utf-8\"><title>Not found</title><link rel=\"icon\" href=\"data:,\">"
    "</head><body style=\"font-family:sans-serif\"><h1>Not found</h1><p><a href=\"/\">Back to lenslab</a></p>"
    "</body></html>";

}  // namespace

void addStaticRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get("/report", [](const httplib::Request&, httplib::Response& res) { res.set_redirect("/report/"); });
    server.Get(std::string("/report/") + kSafeRelativePath, [&parts](const httplib::Request& req, httplib::Response& res) {
        if (serveInside(parts.config.reportDir, req.matches[1], res)) return;
        res.status = 404;
        res.set_content(std::string(req.matches[1]).empty() ? kNoReportPage : kNotFoundPage, "text/html; charset=utf-8");
    });
    server.Get(std::string("/") + kSafeRelativePath, [&parts](const httplib::Request& req, httplib::Response& res) {
        if (req.path.rfind("/api/", 0) == 0) return replyError(res, 404, "no such API path (docs/api.md lists them)");
        if (serveInside(parts.config.webDir, req.matches[1], res)) return;
        res.status = 404;
        res.set_content(kNotFoundPage, "text/html; charset=utf-8");
    });
}

}  // namespace lenslab
