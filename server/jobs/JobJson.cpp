#include "jobs/JobJson.h"

#include "PublicMessage.h"

namespace lenslab {

nlohmann::json jobJson(const JobView& job, std::size_t tilesSince, double now) {
    using nlohmann::json;
    const JobRecord& r = job.record;
    const auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
    const double elapsed = r.started ? r.finished.value_or(now) - *r.started : 0.0;
    json eta = nullptr;
    if (r.state == JobState::Running && r.tilesDone > 0 && r.tilesTotal >= r.tilesDone)
        eta = elapsed / r.tilesDone * (r.tilesTotal - r.tilesDone);
    json tiles = json::array();
    for (std::size_t i = tilesSince; i < job.tiles.size(); ++i)
        tiles.push_back({job.tiles[i].x0, job.tiles[i].y0, job.tiles[i].x1, job.tiles[i].y1});
    const std::string base = "/api/renders/" + r.id;
    json body = {{"id", r.id},
                 {"state", jobStateName(r.state)},
                 {"request", r.request},
                 {"created", r.created},
                 {"started", optional(r.started)},
                 {"finished", optional(r.finished)},
                 {"progress",
                  {{"tiles_done", r.tilesDone},
                   {"tiles_total", r.tilesTotal},
                   {"fraction", r.tilesTotal > 0 ? double(r.tilesDone) / r.tilesTotal : (r.state == JobState::Done ? 1.0 : 0.0)},
                   {"elapsed_s", elapsed},
                   {"eta_s", eta}}},
                 {"tiles_since", tilesSince},
                 {"tiles", tiles},
                 {"cancel_requested", job.cancelRequested},
                 {"interrupted", r.interrupted},
                 {"error", r.error.empty() ? json(nullptr) : json(publicMessage(r.error))},
                 {"stats", r.stats},
                 {"warnings", r.warnings},
                 {"links", {{"self", base}, {"preview", base + "/preview.png"}}}};
    if (r.state == JobState::Done) {
        body["links"]["png"] = base + "/image.png";
        body["links"]["exr"] = base + "/image.exr";
    }
    return body;
}

}  // namespace lenslab
