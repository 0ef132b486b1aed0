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
        const LensStore::Counts lenses = parts.lenses.counts();
        const WorkPoolStats w = parts.work.stats();
        const auto cacheJson = [](const ResultCacheStats& c) {
            return nlohmann::json{{"hits", c.hits}, {"misses", c.misses}, {"entries", c.entries}, {"bytes", c.bytes}};
        };
        replyJson(res, 200,
                  {{"status", "ok"},
                   {"version", LENSLAB_VERSION},
                   {"uptime_s", secondsSinceEpoch() - parts.startedAt},
                   {"lenses", lenses.lenses},
                   {"lenses_loading", lenses.waiting},
                   {"scenes", parts.scenes.list().size()},
                   {"renders", {{"queued", q.queued}, {"running", q.running}, {"max_queued", q.maxQueued},
                                {"concurrent", q.workers}, {"previews_encoded", q.previewsEncoded}}},
                   {"work", {{"threads", w.threads}, {"running", w.running}, {"queued", w.queued},
                             {"admitted", w.admitted}, {"refused", w.refused}}},
                   {"diagram_cache", cacheJson(parts.diagrams.stats())},
                   {"analysis_cache", cacheJson(parts.analyses.stats())}});
    });
    server.Get("/api/version", [](const httplib::Request&, httplib::Response& res) {
        replyJson(res, 200, {{"name", "lenslab"}, {"version", LENSLAB_VERSION}, {"api", 1}});
    });
}

}  // namespace lenslab
