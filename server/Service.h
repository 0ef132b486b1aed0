#pragma once
// The whole service: data folder, database, lens store, scenes, diagram cache, render queue and the
// HTTP server with its routes. Construction recovers from an earlier abrupt stop: half-written
// files are removed, jobs left running are marked interrupted, queued jobs are scheduled again.
#include <memory>

#include "AccessLog.h"
#include "DataFolderLock.h"
#include "DataFolderQuota.h"
#include "Database.h"
#include "DiagramCache.h"
#include "HttpServer.h"
#include "JobQueue.h"
#include "JobStore.h"
#include "LensStore.h"
#include "JobRenderer.h"
#include "ReportJob.h"
#include "SceneCatalog.h"
#include "ServiceConfig.h"
#include "ServiceParts.h"

namespace lenslab {

class Service {
public:
    Service(const ServiceConfig& config, std::unique_ptr<JobRenderer> renderer);
    ~Service();  // stop()

    int start();  // returns the port it listens on
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
    LensStore lenses_;
    SceneCatalog scenes_;
    RenderSettingsChecks renderChecks_;
    DiagramCache diagrams_;
    JobStore jobStore_;
    std::unique_ptr<JobRenderer> renderer_;
    JobQueue jobs_;
    ReportJob report_;
    DataFolderQuota quota_;
    ServiceParts parts_;
    HttpServer http_;
};

}  // namespace lenslab
