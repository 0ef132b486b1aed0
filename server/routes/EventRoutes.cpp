// Server-sent events (text/event-stream) for the page's live progress: a render job's status with
// its newly finished tiles, and the report build's status. Each stream sends an event when
// something changed (and at least once a second while a job runs, so elapsed time and ETA move),
// then ends when the job is over; the page falls back to polling when a stream breaks.
#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>

#include "guards/EventStreamSlots.h"
#include "guards/GuardedServer.h"
#include "core/HttpError.h"
#include "core/Identifiers.h"
#include "jobs/JobJson.h"
#include "routes/ServiceParts.h"
#include "core/WallClock.h"

namespace lenslab {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr auto kCheckEvery = std::chrono::milliseconds(100);
constexpr auto kRefreshEvery = std::chrono::seconds(1);

bool writeEvent(httplib::DataSink& sink, const json& data) {
    const std::string event = "data: " + data.dump(-1, ' ', false, json::error_handler_t::replace) + "\n\n";
    return sink.write(event.data(), event.size());
}

bool isOver(JobState state) { return state == JobState::Done || state == JobState::Failed || state == JobState::Cancelled; }

constexpr std::size_t kStreamsPerClient = 4;

// Streams events until `next` says the job is over, the client leaves or the server stops.
// `next(changedOnly)` returns the event to send (null: nothing new) and whether the job is over.
// The stream holds a slot (503 when none is free) until its answer is done.
template <class Next>
void streamEvents(httplib::Server& server, EventStreamSlots& slots, const httplib::Request& req, httplib::Response& res,
                  Next next) {
    std::shared_ptr<void> slot = slots.take(req.remote_addr);
    if (!slot) {
        res.set_header("Retry-After", "5");
        throw HttpError(503, "too many event streams are open (at most " + std::to_string(slots.total()) + ", " +
                                 std::to_string(slots.perClient()) + " per client); poll the status instead");
    }
    GuardedServer::liftAnswerDeadlineOnThisThread();
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Accel-Buffering", "no");
    res.set_chunked_content_provider(
        "text/event-stream",
        [&server, next, slot, lastSent = Clock::time_point()](std::size_t, httplib::DataSink& sink) mutable {
            for (;;) {
                if (!server.is_running() || !sink.is_writable()) return false;
                const bool refresh = Clock::now() - lastSent >= kRefreshEvery;
                const auto [event, over] = next(!refresh);
                if (!event.is_null()) {
                    if (!writeEvent(sink, event)) return false;
                    lastSent = Clock::now();
                }
                if (over) {
                    sink.done();
                    return true;
                }
                std::this_thread::sleep_for(kCheckEvery);
            }
        });
}

}  // namespace

void addEventRoutes(httplib::Server& server, ServiceParts& parts) {
    const std::size_t streams = static_cast<std::size_t>(std::max(1, parts.config.httpThreads / 4));
    const auto slots = std::make_shared<EventStreamSlots>(streams, std::min(kStreamsPerClient, streams));
    server.Get(R"(/api/renders/([^/]+)/events)", [&server, &parts, slots](const httplib::Request& req, httplib::Response& res) {
        const std::string id = req.matches[1];
        if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid render id");
        if (!parts.jobs.find(id)) throw HttpError(404, "no render with id '" + id + "'");
        std::size_t tilesSent = 0;
        std::string lastKey;
        streamEvents(server, *slots, req, res, [&parts, id, tilesSent, lastKey](bool changedOnly) mutable -> std::pair<json, bool> {
            const auto job = parts.jobs.find(id);
            if (!job) return {json{{"id", id}, {"state", "deleted"}}, true};
            const JobRecord& r = job->record;
            const std::string key = std::string(jobStateName(r.state)) + ":" + std::to_string(r.tilesDone) + ":" +
                                    std::to_string(job->tiles.size()) + ":" + (job->cancelRequested ? "c" : "");
            const bool over = isOver(r.state);
            if (changedOnly && key == lastKey && !over) return {nullptr, false};
            lastKey = key;
            json event = jobJson(*job, std::min(tilesSent, job->tiles.size()), secondsSinceEpoch());
            tilesSent = job->tiles.size();
            return {event, over};
        });
    });

    server.Get(R"(/api/design-jobs/([^/]+)/events)", [&server, &parts, slots](const httplib::Request& req, httplib::Response& res) {
        const std::string id = findDesignJob(parts, req.matches[1]).status["id"];
        std::optional<std::uint64_t> lastVersion;
        streamEvents(server, *slots, req, res, [&parts, id, lastVersion](bool changedOnly) mutable -> std::pair<json, bool> {
            const auto job = parts.designJobs.find(id);
            if (!job) return {json{{"id", id}, {"state", "deleted"}}, true};
            if (changedOnly && lastVersion == job->version && !job->over) return {nullptr, false};
            lastVersion = job->version;
            return {job->status, job->over};
        });
    });

    server.Get("/api/report/events", [&server, &parts, slots](const httplib::Request& req, httplib::Response& res) {
        std::string lastSent;
        streamEvents(server, *slots, req, res, [&parts, lastSent](bool changedOnly) mutable -> std::pair<json, bool> {
            json status = parts.report.status();
            const bool over = status["state"] != "running";
            const std::string text = status.dump();
            if (changedOnly && text == lastSent && !over) return {nullptr, false};
            lastSent = text;
            return {status, over};
        });
    });
}

}  // namespace lenslab
