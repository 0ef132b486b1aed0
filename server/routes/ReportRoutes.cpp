// /api/report: build the report site served at /report/ as a job (POST), follow it (GET), stop it
// (DELETE). The body may name lenses: bundled ids limit the report to those, uploaded ids are added
// to it (naming only uploads gives every bundled lens plus them); and the quality and the size.
#include <set>

#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/JsonBody.h"
#include "jobs/ReportJob.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

using nlohmann::json;

int boundedInteger(const json& body, const char* name, int fallback, int lo, int hi) {
    if (!body.contains(name)) return fallback;
    const json& v = body[name];
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
        throw HttpError(400, std::string(name) + " must be an integer from " + std::to_string(lo) + " to " +
                                 std::to_string(hi));
    return v.get<int>();
}

// More ids than this in "lenses" is refused: each lens costs the build minutes of rendering.
constexpr std::size_t kMaxReportLenses = 64;

ReportOptions reportOptions(const ServiceParts& parts, const json& body) {
    if (!body.is_object()) throw HttpError(400, "the body must be a JSON object (or empty)");
    for (const auto& item : body.items())
        if (item.key() != "quick" && item.key() != "spp" && item.key() != "width" && item.key() != "lenses")
            throw HttpError(400, "unknown field '" + item.key().substr(0, 40) + "' (quick, spp, width and lenses are known)");
    ReportOptions o;
    o.outputDir = parts.config.reportDir;
    o.lensDir = parts.config.lensesDir;
    o.sceneDir = parts.config.scenesDir;
    o.threads = parts.config.limits.threadsPerRender;
    if (body.contains("quick")) {
        if (!body["quick"].is_boolean()) throw HttpError(400, "quick must be true or false");
        o.quick = body["quick"].get<bool>();
    }
    o.spp = boundedInteger(body, "spp", o.spp, 1, parts.config.limits.maxSpp);
    o.width = boundedInteger(body, "width", o.width, 16, parts.config.limits.maxWidth);
    if (body.contains("lenses")) {
        if (!body["lenses"].is_array()) throw HttpError(400, "lenses must be an array of lens ids");
        if (body["lenses"].size() > kMaxReportLenses)
            throw HttpError(400, "lenses may name at most " + std::to_string(kMaxReportLenses) + " lenses");
        std::set<std::string> named;
        for (const json& id : body["lenses"]) {
            if (!id.is_string()) throw HttpError(400, "lenses must be an array of lens ids");
            if (!named.insert(id.get<std::string>()).second) continue;  // named twice: built once
            const auto lens = findLens(parts, id.get<std::string>());
            // Only the lenses named: an uploaded one by its stored file (its id is the file's stem),
            // headed by the name it was uploaded as.
            o.lenses.push_back(lens->bundled ? lens->id : lens->path);
            if (!lens->bundled) o.lensNames[lens->path] = lens->name;
        }
    }
    return o;
}

}  // namespace

void addReportRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Post("/api/report", [&parts](const httplib::Request& req, httplib::Response& res) {
        const json body = req.body.empty() ? json::object() : parseJsonBody(req, "the body");
        parts.report.start(reportOptions(parts, body));
        res.set_header("Location", "/api/report");
        replyJson(res, 202, parts.report.status());
    });
    server.Get("/api/report", [&parts](const httplib::Request&, httplib::Response& res) {
        replyJson(res, 200, parts.report.status());
    });
    server.Delete("/api/report", [&parts](const httplib::Request&, httplib::Response& res) {
        if (!parts.report.cancel()) throw HttpError(409, "no report build is running");
        replyJson(res, 202, parts.report.status());
    });
}

}  // namespace lenslab
