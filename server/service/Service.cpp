#include "service/Service.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "storage/AtomicFile.h"
#include "jobs/RenderJobResolver.h"
#include "jobs/RenderRetention.h"
#include "storage/StorageError.h"
#include "core/WallClock.h"

namespace lenslab {

namespace {

namespace fs = std::filesystem;

// The folders as absolute paths: messages name files by their paths, and the public ones are cut to
// file names (PublicMessage.h), which a relative path ("data/lenses/...") would escape.
ServiceConfig withAbsoluteFolders(ServiceConfig config) {
    for (std::string* folder : {&config.dataDir, &config.lensesDir, &config.scenesDir, &config.webDir, &config.reportDir})
        if (!folder->empty()) *folder = fs::absolute(*folder).lexically_normal().string();
    return config;
}

WorkPoolLimits workPoolLimits(const ServiceConfig& config) {
    WorkPoolLimits limits;
    limits.threads = config.work.threads > 0 ? config.work.threads : std::max(1u, std::thread::hardware_concurrency());
    limits.admitted = std::max(1, config.httpThreads / 4);
    limits.perClient = config.work.perClient;
    return limits;
}

// Render images being sent: a quarter of the HTTP workers at most (as event streams and heavy work),
// so that a quarter always answers the rest, and a few per client address.
std::shared_ptr<EventStreamSlots> downloadSlots(const ServiceConfig& config) {
    const int total = std::max(1, config.httpThreads / 4);
    return std::make_shared<EventStreamSlots>(static_cast<std::size_t>(total),
                                              static_cast<std::size_t>(std::clamp(config.http.downloadsPerClient, 1, total)));
}

// Prepares the data folder before anything opens files in it.
std::string databasePath(const ServiceConfig& config) {
    fs::create_directories(config.dataDir);
    const int removed = removeStaleTemporaries(config.dataDir);
    if (removed > 0) std::cerr << "lenslab serve: removed " << removed << " half-written files\n";
    return (fs::path(config.dataDir) / "lenslab.db").string();
}

// The quota the operator gave, or the default lowered to what the disk has room for (said at start).
std::uintmax_t dataQuota(const ServiceConfig& config) {
    if (config.maxDataBytesGiven || config.maxDataBytes == 0) return config.maxDataBytes;
    const std::uintmax_t quota = quotaWithinDisk(config.dataDir, config.maxDataBytes);
    if (quota < config.maxDataBytes)
        std::cerr << "lenslab serve: data folder quota " << quota / 1000000 << " MB (the disk's free space and what the "
                  << "folder holds; less than the default " << config.maxDataBytes / 1000000 << " MB; --max-data-gb sets it)\n";
    return quota;
}

}  // namespace

Service::Service(const ServiceConfig& config, std::unique_ptr<JobRenderer> renderer)
    : config_(withAbsoluteFolders(config)),
      accessLog_(config_.accessLogPath),
      lock_(config_.dataDir),
      database_(databasePath(config_)),
      glassCatalogs_((fs::path(config_.dataDir) / "glass-catalogs").string(), database_),
      lenses_(config_.lensesDir, (fs::path(config_.dataDir) / "lenses").string(), database_, config_.maxUploadedLenses),
      scenes_(config_.scenesDir),
      diagrams_(config_.diagramCacheBytes),
      analyses_(config_.analysisCacheBytes),
      work_(workPoolLimits(config_)),
      jobStore_(database_),
      renderer_(std::move(renderer)),
      jobs_(jobStore_, *renderer_, config_.limits, (fs::path(config_.dataDir) / "renders").string()),
      report_(work_),
      designJobs_(work_),
      quota_(config_.dataDir, dataQuota(config_), [this] { collectFinishedRenders(); }),
      downloads_(downloadSlots(config_)),
      parts_{config_, lenses_, glassCatalogs_, scenes_, renderChecks_, diagrams_, analyses_, work_, jobs_, report_, designJobs_,
             quota_, *downloads_, secondsSinceEpoch()},
      http_(config_, accessLog_) {
    recoverJobs();
    jobs_.setAfterJob([this] { collectFinishedRenders(); });
    addHealthRoutes(http_.routes(), parts_);
    addLensRoutes(http_.routes(), parts_);
    addAnalysisRoutes(http_.routes(), parts_);
    addPrescriptionRoutes(http_.routes(), parts_);
    addGlassRoutes(http_.routes(), parts_);
    addGlassCatalogRoutes(http_.routes(), parts_);
    addDiagramRoutes(http_.routes(), parts_);
    addRenderRoutes(http_.routes(), parts_);
    addReportRoutes(http_.routes(), parts_);
    addDesignRoutes(http_.routes(), parts_);
    addEventRoutes(http_.routes(), parts_);
    addImageRoutes(http_.routes(), parts_);
    addStaticRoutes(http_.routes(), parts_);
}

Service::~Service() { stop(); }

void Service::recoverJobs() {
    try {
        const int interrupted = jobStore_.markInterrupted();
        if (interrupted > 0) std::cerr << "lenslab serve: " << interrupted << " render(s) were interrupted; marked failed\n";
        restoreQueuedJobs();
        for (const std::string& id : jobStore_.withoutImageBytes())
            jobStore_.setImageBytes(id, static_cast<std::int64_t>(jobs_.imageBytes(id)));
        collectFinishedRenders();
    } catch (const StorageError& e) {
        // A full or read-only disk must not keep the service down: reads work, writes say why.
        std::cerr << "lenslab serve: the data folder cannot be written (" << e.detail() << "); serving anyway: "
                  << e.what() << "\n";
    }
}

void Service::restoreQueuedJobs() {
    for (JobRecord record : jobStore_.queued()) {
        try {
            const RenderRequest request = parseRenderRequest(record.request, config_.limits, "");
            jobs_.restore(record, resolveRenderJob(record.id, request, lenses_, scenes_, renderChecks_));
        } catch (const std::exception& e) {
            record.state = JobState::Failed;
            record.finished = secondsSinceEpoch();
            record.error = std::string("could not be restarted: ") + e.what();
            jobStore_.save(record);
        }
    }
}

void Service::collectFinishedRenders() { collectRenders(jobs_, jobStore_, config_.retention, secondsSinceEpoch()); }

int Service::start() {
    const int port = http_.start(config_.host, config_.port);
    lenses_.describeInBackground();
    return port;
}

void Service::stop() {
    http_.stop();
    jobs_.shutdown();
}

}  // namespace lenslab
