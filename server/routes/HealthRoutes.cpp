// GET /api/health (liveness with queue and cache figures) and GET /api/version.
#include "core/HttpReply.h"
#include "routes/ServiceParts.h"
#include "core/WallClock.h"

#ifndef LENSLAB_VERSION
#error "LENSLAB_VERSION must be defined by the build"
#endif

namespace lenslab {

void addHealthRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get("/api/health", [&parts](const httplib::Request&, httplib::Response& res) {
        const QueueCounts q = parts.jobs.counts();
        const DiagramCacheStats d = parts.diagrams.stats();
        replyJson(res, 200,
                  {{"status", "ok"},
                   {"version", LENSLAB_VERSION},
                   {"uptime_s", secondsSinceEpoch() - parts.startedAt},
                   {"lenses", parts.lenses.list().size()},
                   {"scenes", parts.scenes.list().size()},
                   {"renders", {{"queued", q.queued}, {"running", q.running}, {"max_queued", q.maxQueued},
                                {"concurrent", q.workers}}},
                   {"diagram_cache", {{"hits", d.hits}, {"misses", d.misses}, {"entries", d.entries}, {"bytes", d.bytes}}}});
    });
    server.Get("/api/version", [](const httplib::Request&, httplib::Response& res) {
        replyJson(res, 200, {{"name", "lenslab"}, {"version", LENSLAB_VERSION}, {"api", 1}});
    });
}

}  // namespace lenslab
