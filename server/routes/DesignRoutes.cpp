// The design jobs: POST /api/lenses/{id}/optimise and POST /api/lenses/{id}/tolerance (202 and the
// job), GET /api/design-jobs/{id} (status, progress, result) and DELETE (cancel, or forget a finished
// one); their progress as server-sent events is in EventRoutes.cpp. The body is read against the lens
// at once (jobs/DesignRequest.h: 400 naming the field), then the work waits its turn in the heavy-work
// pool holding the client's place there (jobs/DesignJobs.h).
#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/Identifiers.h"
#include "core/JsonBody.h"
#include "jobs/DesignRequest.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

using nlohmann::json;

// A merit or a tolerance specification is a few KiB; thousands of operands would make every
// evaluation of a job slow.
constexpr std::size_t kMaxDesignBody = 64 * 1024;

using ReadWork = DesignWork (*)(const LensTable&, const json&);

void submit(ServiceParts& parts, const httplib::Request& req, httplib::Response& res, const char* kind, ReadWork read) {
    if (req.body.size() > kMaxDesignBody)
        throw HttpError(413, std::string("a ") + kind + " request's body is at most " + std::to_string(kMaxDesignBody / 1024) + " KiB");
    const auto lens = findLens(parts, req.matches[1]);
    const json body = req.body.empty() ? json::object() : parseJsonBody(req, "the body");
    DesignWork work;
    try {
        work = read(storedTable(*lens), body);
    } catch (const DesignRequestError& e) {
        replyJson(res, 400, {{"error", e.what()}, {"field", e.field()}});
        return;
    }
    const DesignJobView job = parts.designJobs.start(kind, lens->id, parts.work.admit(clientOf(req)), std::move(work));
    res.set_header("Location", job.status["links"]["self"].get<std::string>());
    replyJson(res, 202, job.status);
}

}  // namespace

DesignJobView findDesignJob(const ServiceParts& parts, const std::string& id) {
    if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid design job id");
    auto job = parts.designJobs.find(id);
    if (!job) throw HttpError(404, "no design job with id '" + id + "'");
    return *job;
}

void addDesignRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Post(R"(/api/lenses/([^/]+)/optimise)", [&parts](const httplib::Request& req, httplib::Response& res) {
        submit(parts, req, res, "optimise", optimiseWork);
    });
    server.Post(R"(/api/lenses/([^/]+)/tolerance)", [&parts](const httplib::Request& req, httplib::Response& res) {
        submit(parts, req, res, "tolerance", toleranceWork);
    });
    server.Get(R"(/api/design-jobs/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        replyJson(res, 200, findDesignJob(parts, req.matches[1]).status);
    });
    server.Delete(R"(/api/design-jobs/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = findDesignJob(parts, req.matches[1]).status["id"];
        switch (parts.designJobs.cancel(id)) {
            case DesignJobs::Cancel::Cancelled:
                replyJson(res, 200, {{"id", id}, {"state", "cancelled"}});
                return;
            case DesignJobs::Cancel::Requested:
                replyJson(res, 202, {{"id", id}, {"state", "running"}, {"cancel_requested", true}});
                return;
            case DesignJobs::Cancel::Deleted:
                replyJson(res, 200, {{"id", id}, {"deleted", true}});
                return;
            case DesignJobs::Cancel::NotFound:
                throw HttpError(404, "no design job with id '" + id + "'");
        }
    });
}

}  // namespace lenslab
