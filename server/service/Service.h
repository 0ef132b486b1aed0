#pragma once
// The whole service: data folder, database, lens store, scenes, diagram cache, render queue and the
// HTTP server with its routes. Construction recovers from an earlier abrupt stop: half-written
// files are removed, jobs left running are marked interrupted, queued jobs are scheduled again.
#include <memory>

#include "guards/AccessLog.h"
#include "storage/DataFolderLock.h"
#include "storage/DataFolderQuota.h"
#include "storage/Database.h"
#include "storage/ResultCache.h"
#include "service/HttpServer.h"
#include "jobs/DesignJobs.h"
#include "jobs/JobQueue.h"
#include "jobs/JobStore.h"
#include "storage/LensStore.h"
#include "jobs/JobRenderer.h"
#include "jobs/ReportJob.h"
#include "jobs/WorkPool.h"
#include "storage/SceneCatalog.h"
#include "core/ServiceConfig.h"
#include "routes/ServiceParts.h"

namespace lenslab {

class Service {
public:
    Service(const ServiceConfig& config, std::unique_ptr<JobRenderer> renderer);
    ~Service();  // stop()

    // Listens, then describes the stored uploads in the background; returns the port.
    int start();
    // Stops listening, then stops the render workers (running jobs go back to the queue).
    void stop();

private:
    void recoverJobs();  // after an abrupt stop; tolerates a data folder that cannot be written
    void restoreQueuedJobs();
    void collectFinishedRenders();  // by the retention policy

    ServiceConfig config_;
    AccessLog accessLog_;
    DataFolderLock lock_;  // before anything touches the folder
    Database database_;
    GlassCatalogStore glassCatalogs_;  // before any lens is read: their glasses may come from these
    LensStore lenses_;
    SceneCatalog scenes_;
    RenderSettingsChecks renderChecks_;
    ResultCache diagrams_;
    ResultCache analyses_;
    WorkPool work_;  // before the report, whose build it runs
    JobStore jobStore_;
    std::unique_ptr<JobRenderer> renderer_;
    JobQueue jobs_;
    ReportJob report_;
    DesignJobs designJobs_;  // after the pool, which runs them
    DataFolderQuota quota_;
    std::shared_ptr<EventStreamSlots> downloads_;
    ServiceParts parts_;
    HttpServer http_;
};

}  // namespace lenslab
