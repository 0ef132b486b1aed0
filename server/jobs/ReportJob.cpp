#include "jobs/ReportJob.h"

#include "core/HttpError.h"
#include "core/WallClock.h"
#include "PublicMessage.h"

namespace lenslab {

ReportJob::~ReportJob() {
    cancel_ = true;
    if (build_.valid()) build_.wait();
}

void ReportJob::start(const ReportOptions& options) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (state_ == "running") throw HttpError(409, "a report build is already running");
    if (build_.valid()) build_.wait();  // the previous build has finished
    cancel_ = false;
    state_ = "running";
    progress_ = {};
    outcome_ = nullptr;
    started_ = secondsSinceEpoch();
    finished_ = 0;
    auto build = std::make_shared<std::packaged_task<void()>>([this, options] { run(options); });
    build_ = build->get_future();
    pool_.post([build] { (*build)(); });
}

bool ReportJob::cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (state_ != "running") return false;
    cancel_ = true;
    return true;
}

void ReportJob::run(ReportOptions options) {
    std::string state = "done";
    nlohmann::json outcome;
    try {
        const ReportSummary s = buildReport(
            options,
            [this](const ReportProgress& p) {
                std::lock_guard<std::mutex> lock(mutex_);
                progress_ = p;
            },
            &cancel_);
        outcome = {{"summary",
                    {{"items", s.items}, {"built", s.built}, {"reused", s.reused}, {"renders", s.renders},
                     {"lenses", s.lenses}, {"scenes", s.scenes}, {"seconds", s.seconds}, {"problems", s.problems}}}};  // public already
    } catch (const ReportCancelled&) {
        state = "cancelled";
    } catch (const std::exception& e) {
        state = "failed";
        outcome = {{"error", publicMessage(e.what())}};
    }
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = state;
    outcome_ = outcome;
    finished_ = secondsSinceEpoch();
}

nlohmann::json ReportJob::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    nlohmann::json j = {{"state", state_},
                        {"progress", {{"done", progress_.done}, {"total", progress_.total}, {"item", progress_.item}}},
                        {"url", "/report/"}};
    if (started_ > 0) j["started"] = started_;
    if (finished_ > 0) j["finished"] = finished_;
    if (outcome_.is_object()) j.update(outcome_);
    return j;
}

}  // namespace lenslab
