// /api/scenes and /api/renders: submit, list, status with progress, the partial image while it
// renders, the finished PNG and EXR, cancellation and resubmission.
#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/Identifiers.h"
#include "core/JsonBody.h"
#include "jobs/JobJson.h"
#include "core/QueryParameters.h"
#include "jobs/RenderJobResolver.h"
#include "routes/ServiceParts.h"
#include "core/WallClock.h"

namespace lenslab {

namespace {

using nlohmann::json;

std::string jobIdFrom(const httplib::Request& req) {
    const std::string id = req.matches[1];
    if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid render id");
    return id;
}

JobView findJob(const ServiceParts& parts, const std::string& id) {
    auto job = parts.jobs.find(id);
    if (!job) throw HttpError(404, "no render with id '" + id + "'");
    return *job;
}

void submit(ServiceParts& parts, const RenderRequest& request, httplib::Response& res) {
    parts.quota.checkRoomForWrite();
    // From the lens's lookup until the job is queued: a deletion of the lens waits, then sees the job.
    const auto lensKept = parts.lenses.holdLenses();
    const RenderJobInput input = resolveRenderJob(newRandomIdentifier("render-"), request, parts.lenses, parts.scenes, parts.renderChecks);
    try {
        const JobRecord record = parts.jobs.submit(input);
        res.set_header("Location", "/api/renders/" + record.id);
        replyJson(res, 202, jobJson(JobView{record, false, {}}, 0, secondsSinceEpoch()));
    } catch (const QueueFull& e) {
        res.set_header("Retry-After", "10");
        const QueueCounts counts = parts.jobs.counts();
        replyJson(res, 429, {{"error", e.what()}, {"queued", counts.queued}, {"max_queued", counts.maxQueued}});
    }
}

std::string defaultScene(const ServiceParts& parts) {
    return parts.scenes.list().empty() ? "" : parts.scenes.list().front().id;
}

}  // namespace

std::shared_ptr<void> takeDownloadSlot(ServiceParts& parts, const httplib::Request& req) {
    if (auto slot = parts.downloads.take(clientOf(req))) return slot;
    throw HttpError(429, "too many render images are being sent (at most " + std::to_string(parts.downloads.total()) +
                             " at once, " + std::to_string(parts.downloads.perClient()) +
                             " to one client); ask again when one has arrived", 2);
}

namespace {

void sendImage(ServiceParts& parts, const httplib::Request& req, httplib::Response& res, const std::string& format) {
    const JobView job = findJob(parts, jobIdFrom(req));
    if (job.record.state != JobState::Done)
        throw HttpError(409, "render '" + job.record.id + "' is " + jobStateName(job.record.state) + ", not done");
    const std::string type = format == "png" ? "image/png" : "image/x-exr";
    if (!replyFile(res, parts.jobs.imagePath(job.record.id, format), type, takeDownloadSlot(parts, req)))
        throw HttpError(404, "the image of render '" + job.record.id + "' is no longer on disk");
    res.set_header("Content-Disposition", "inline; filename=\"" + job.record.id + "." + format + "\"");
}

}  // namespace

void addRenderRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get("/api/scenes", [&parts](const httplib::Request&, httplib::Response& res) {
        json list = json::array();
        for (const SceneEntry& s : parts.scenes.list()) list.push_back({{"id", s.id}, {"title", s.title}});
        replyJson(res, 200, {{"scenes", list}});
    });

    server.Post("/api/renders", [&parts](const httplib::Request& req, httplib::Response& res) {
        submit(parts, parseRenderRequest(parseJsonBody(req, "the render request"), parts.config.limits, defaultScene(parts)), res);
    });

    server.Get("/api/renders", [&parts](const httplib::Request&, httplib::Response& res) {
        const QueueCounts counts = parts.jobs.counts();
        json list = json::array();
        const double now = secondsSinceEpoch();
        for (const JobView& job : parts.jobs.recent(50)) list.push_back(jobJson(job, job.tiles.size(), now));
        replyJson(res, 200,
                  {{"renders", list},
                   {"queue", {{"queued", counts.queued}, {"running", counts.running}, {"max_queued", counts.maxQueued},
                              {"concurrent", counts.workers}}}});
    });

    server.Get(R"(/api/renders/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        const JobView job = findJob(parts, jobIdFrom(req));
        const auto since = queryNumber(req, "tiles_since", 0, 1e9).value_or(0);
        replyJson(res, 200, jobJson(job, static_cast<std::size_t>(since), secondsSinceEpoch()));
    });

    server.Get(R"(/api/renders/([^/]+)/preview\.png)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = jobIdFrom(req);
        if (PreviewPng png = parts.jobs.preview(id)) {
            replySharedBytes(res, std::move(png), "image/png", takeDownloadSlot(parts, req));
            res.set_header("Cache-Control", "no-store");
            return;
        }
        const JobView job = findJob(parts, id);
        if (job.record.state == JobState::Done) return sendImage(parts, req, res, "png");
        throw HttpError(409, "render '" + id + "' has no finished tiles to show (" + jobStateName(job.record.state) + ")");
    });

    server.Get(R"(/api/renders/([^/]+)/image\.png)",
               [&parts](const httplib::Request& req, httplib::Response& res) { sendImage(parts, req, res, "png"); });
    server.Get(R"(/api/renders/([^/]+)/image\.exr)",
               [&parts](const httplib::Request& req, httplib::Response& res) { sendImage(parts, req, res, "exr"); });

    server.Delete(R"(/api/renders/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = jobIdFrom(req);
        switch (parts.jobs.cancel(id)) {
            case JobQueue::Cancel::Cancelled:
                replyJson(res, 200, {{"id", id}, {"state", "cancelled"}});
                return;
            case JobQueue::Cancel::Requested:
                replyJson(res, 202, {{"id", id}, {"state", "running"}, {"cancel_requested", true}});
                return;
            case JobQueue::Cancel::AlreadyFinished:
                if (parts.jobs.removeFinished(id) != JobQueue::Removal::Removed)
                    throw HttpError(409, "render '" + id + "' changed state meanwhile; try again");
                replyJson(res, 200, {{"id", id}, {"deleted", true}});
                return;
            case JobQueue::Cancel::NotFound:
                throw HttpError(404, "no render with id '" + id + "'");
        }
    });

    server.Post(R"(/api/renders/([^/]+)/resubmit)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const JobView job = findJob(parts, jobIdFrom(req));
        if (job.record.state == JobState::Queued || job.record.state == JobState::Running)
            throw HttpError(409, "render '" + job.record.id + "' is still " + jobStateName(job.record.state));
        submit(parts, parseRenderRequest(job.record.request, parts.config.limits, defaultScene(parts)), res);
    });
}

}  // namespace lenslab
