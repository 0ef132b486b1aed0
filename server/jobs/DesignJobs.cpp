#include "jobs/DesignJobs.h"

#include <algorithm>

#include "core/Identifiers.h"
#include "core/WallClock.h"
#include "PublicMessage.h"

namespace lenslab {

using nlohmann::json;

struct DesignJobs::Job {
    std::string id, kind, lensId;
    std::string state = "queued";  // queued | running | done | failed | cancelled
    json progress = nullptr;
    json outcome = nullptr;  // {"result": ...} or {"error": ...}
    double created = 0, started = 0, finished = 0;
    std::atomic<bool> cancel{false};
    std::unique_ptr<WorkPool::Admission> admission;  // the client's place, until the job ends
    std::uint64_t version = 0;
};

class DesignJobs::Control : public DesignJobControl {
public:
    Control(DesignJobs& jobs, std::shared_ptr<Job> job) : jobs_(jobs), job_(std::move(job)) {}
    bool cancelled() const override { return job_->cancel.load(); }
    void report(json progress) override {
        std::lock_guard<std::mutex> lock(jobs_.mutex_);
        job_->progress = std::move(progress);
        ++job_->version;
    }

private:
    DesignJobs& jobs_;
    std::shared_ptr<Job> job_;
};

DesignJobs::~DesignJobs() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (auto& [id, job] : jobs_) job->cancel = true;
    idle_.wait(lock, [&] { return inPool_ == 0; });
}

DesignJobView DesignJobs::start(const std::string& kind, const std::string& lensId, WorkPool::Admission admission, DesignWork work) {
    auto job = std::make_shared<Job>();
    job->id = newRandomIdentifier("design-");
    job->kind = kind;
    job->lensId = lensId;
    job->created = secondsSinceEpoch();
    job->admission = std::make_unique<WorkPool::Admission>(std::move(admission));
    std::lock_guard<std::mutex> lock(mutex_);
    jobs_[job->id] = job;
    ++inPool_;
    pool_.post([this, job, work = std::move(work)] {
        run(job, work);
        std::lock_guard<std::mutex> lock(mutex_);
        --inPool_;
        idle_.notify_all();
    });
    return viewOf(*job);
}

void DesignJobs::run(const std::shared_ptr<Job>& job, const DesignWork& work) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (job->state != "queued") return;  // cancelled while it waited
        job->state = "running";
        job->started = secondsSinceEpoch();
        ++job->version;
    }
    Control control(*this, job);
    std::string state = "done";
    json outcome;
    try {
        outcome = {{"result", work(control)}};
    } catch (const std::exception& e) {
        state = "failed";
        outcome = {{"error", publicMessage(e.what())}};
    }
    if (job->cancel) state = "cancelled", outcome = nullptr;  // a cancelled run's partial result is not the answer
    std::lock_guard<std::mutex> lock(mutex_);
    finish(*job, state, std::move(outcome));
}

void DesignJobs::finish(Job& job, const std::string& state, json outcome) {
    job.state = state;
    job.outcome = std::move(outcome);
    job.finished = secondsSinceEpoch();
    job.admission.reset();
    ++job.version;
    finishedOrder_.push_back(job.id);
    while (finishedOrder_.size() > kKeptFinished) {
        jobs_.erase(finishedOrder_.front());
        finishedOrder_.pop_front();
    }
}

std::optional<DesignJobView> DesignJobs::find(const std::string& id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = jobs_.find(id);
    if (it == jobs_.end()) return std::nullopt;
    return viewOf(*it->second);
}

DesignJobs::Cancel DesignJobs::cancel(const std::string& id) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = jobs_.find(id);
    if (it == jobs_.end()) return Cancel::NotFound;
    Job& job = *it->second;
    if (job.state == "queued" || job.state == "running") {
        job.cancel = true;
        ++job.version;
        if (job.state == "running") return Cancel::Requested;
        finish(job, "cancelled", nullptr);
        return Cancel::Cancelled;
    }
    finishedOrder_.erase(std::find(finishedOrder_.begin(), finishedOrder_.end(), id));
    jobs_.erase(it);
    return Cancel::Deleted;
}

DesignJobView DesignJobs::viewOf(const Job& job) const {
    json status = {{"id", job.id},
                   {"kind", job.kind},
                   {"lens", job.lensId},
                   {"state", job.state},
                   {"progress", job.progress},
                   {"cancel_requested", job.cancel.load()},
                   {"created", job.created},
                   {"started", job.started > 0 ? json(job.started) : json(nullptr)},
                   {"finished", job.finished > 0 ? json(job.finished) : json(nullptr)},
                   {"links", {{"self", "/api/design-jobs/" + job.id}, {"events", "/api/design-jobs/" + job.id + "/events"}}}};
    if (job.outcome.is_object()) status.update(job.outcome);
    const bool over = job.state == "done" || job.state == "failed" || job.state == "cancelled";
    return {status, job.version, over};
}

}  // namespace lenslab
