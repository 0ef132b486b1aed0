#pragma once
// What the route handlers work with; owned by Service, which outlives the HTTP server.
#include <httplib.h>

#include "guards/EventStreamSlots.h"
#include "storage/DataFolderQuota.h"
#include "storage/ResultCache.h"
#include "jobs/DesignJobs.h"
#include "jobs/JobQueue.h"
#include "storage/GlassCatalogStore.h"
#include "storage/LensStore.h"
#include "jobs/RenderSettingsChecks.h"
#include "jobs/ReportJob.h"
#include "jobs/WorkPool.h"
#include "storage/SceneCatalog.h"
#include "core/ServiceConfig.h"

namespace lenslab {

struct ServiceParts {
    const ServiceConfig& config;
    LensStore& lenses;
    GlassCatalogStore& glassCatalogs;  // uploaded .agf files, their glasses in the lookup
    const SceneCatalog& scenes;
    RenderSettingsChecks& renderChecks;  // render requests against their scene's camera and lens
    ResultCache& diagrams;   // PNGs by lens id and drawing
    ResultCache& analyses;   // analyses, previews, glass catalogs and stored lenses written out, as text, by all they depend on
    WorkPool& work;          // where heavy work runs (analyses, previews, diagrams, uploads, reports)
    JobQueue& jobs;
    ReportJob& report;
    DesignJobs& designJobs;  // optimisations and tolerance analyses
    DataFolderQuota& quota;  // checked before uploads and render submissions
    EventStreamSlots& downloads;  // render images being sent: a slow reader holds a worker throughout
    double startedAt;  // seconds since the epoch
};

// The lens a URL names: HttpError 400 for an id outside the safe alphabet, 404 for an unknown one.
std::shared_ptr<const StoredLens> findLens(const ServiceParts& parts, const std::string& id);

// A stored lens's table as its file holds it, named as the page names the lens.
LensTable storedTable(const StoredLens& lens);

// The design job a URL names: HttpError 400 for an id outside the safe alphabet, 404 for an unknown one.
DesignJobView findDesignJob(const ServiceParts& parts, const std::string& id);

// What a result computed from a stored lens depends on besides the request's settings: the table's
// text (two uploads of one table share it) and the glass catalogs its glasses were looked up in.
std::string lensContentKey(const ServiceParts& parts, const StoredLens& lens);

// Who is asking, for the heavy-work pool's per-client share: the client's address.
inline const std::string& clientOf(const httplib::Request& req) { return req.remote_addr; }

// A render image's hold on its HTTP worker while it is sent (keep it with the answer's content
// provider): HttpError 429 with Retry-After when the client holds its share or downloads hold all
// the workers they may.
std::shared_ptr<void> takeDownloadSlot(ServiceParts& parts, const httplib::Request& req);

void addHealthRoutes(httplib::Server& server, ServiceParts& parts);
void addLensRoutes(httplib::Server& server, ServiceParts& parts);
void addAnalysisRoutes(httplib::Server& server, ServiceParts& parts);
void addPrescriptionRoutes(httplib::Server& server, ServiceParts& parts);  // the live editor
void addGlassRoutes(httplib::Server& server, ServiceParts& parts);
void addGlassCatalogRoutes(httplib::Server& server, ServiceParts& parts);
void addDiagramRoutes(httplib::Server& server, ServiceParts& parts);
void addRenderRoutes(httplib::Server& server, ServiceParts& parts);
void addReportRoutes(httplib::Server& server, ServiceParts& parts);
void addDesignRoutes(httplib::Server& server, ServiceParts& parts);  // optimise and tolerance jobs
void addEventRoutes(httplib::Server& server, ServiceParts& parts);
void addImageRoutes(httplib::Server& server, ServiceParts& parts);
void addStaticRoutes(httplib::Server& server, ServiceParts& parts);  // last: it owns "/"

}  // namespace lenslab
