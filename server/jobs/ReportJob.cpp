#include "jobs/ReportJob.h"

#include "core/HttpError.h"
#include "core/WallClock.h"

namespace lenslab {

ReportJob::~ReportJob() {
    cancel_ = true;
    if (worker_.joinable()) worker_.join();
}

void ReportJob::start(const ReportOptions& options) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (state_ == "running") throw HttpError(409, "a report build is already running");
    if (worker_.joinable()) worker_.join();  // the previous build has finished
    cancel_ = false;
    state_ = "running";
    progress_ = {};
    outcome_ = nullptr;
    started_ = secondsSinceEpoch();
    finished_ = 0;
    worker_ = std::thread(&ReportJob::run, this, options);
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
                     {"lenses", s.lenses}, {"scenes", s.scenes}, {"seconds", s.seconds}, {"problems", s.problems}}}};
    } catch (const ReportCancelled&) {
        state = "cancelled";
    } catch (const std::exception& e) {
        state = "failed";
        outcome = {{"error", e.what()}};
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
