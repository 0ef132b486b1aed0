#pragma once
// What the route handlers work with; owned by Service, which outlives the HTTP server.
#include <httplib.h>

#include "storage/DataFolderQuota.h"
#include "storage/DiagramCache.h"
#include "jobs/JobQueue.h"
#include "storage/LensStore.h"
#include "jobs/RenderSettingsChecks.h"
#include "jobs/ReportJob.h"
#include "storage/SceneCatalog.h"
#include "core/ServiceConfig.h"

namespace lenslab {

struct ServiceParts {
    const ServiceConfig& config;
    LensStore& lenses;
    const SceneCatalog& scenes;
    RenderSettingsChecks& renderChecks;  // render requests against their scene's camera and lens
    DiagramCache& diagrams;
    JobQueue& jobs;
    ReportJob& report;
    DataFolderQuota& quota;  // checked before uploads and render submissions
    double startedAt;  // seconds since the epoch
};

// The lens a URL names: HttpError 400 for an id outside the safe alphabet, 404 for an unknown one.
std::shared_ptr<const StoredLens> findLens(const ServiceParts& parts, const std::string& id);

void addHealthRoutes(httplib::Server& server, ServiceParts& parts);
void addLensRoutes(httplib::Server& server, ServiceParts& parts);
void addAnalysisRoutes(httplib::Server& server, ServiceParts& parts);
void addPrescriptionRoutes(httplib::Server& server, ServiceParts& parts);  // the live editor
void addGlassRoutes(httplib::Server& server, ServiceParts& parts);
void addDiagramRoutes(httplib::Server& server, ServiceParts& parts);
void addRenderRoutes(httplib::Server& server, ServiceParts& parts);
void addReportRoutes(httplib::Server& server, ServiceParts& parts);
void addEventRoutes(httplib::Server& server, ServiceParts& parts);
void addImageRoutes(httplib::Server& server, ServiceParts& parts);
void addStaticRoutes(httplib::Server& server, ServiceParts& parts);  // last: it owns "/"

}  // namespace lenslab
