#include "ServeCommand.h"

#include <malloc.h>
#include <signal.h>

#include <filesystem>
#include <iostream>

#include "guards/AccessControl.h"
#include "Commands.h"
#include "jobs/EngineRenderer.h"
#include "jobs/MpiRenderer.h"
#include "ServeOptions.h"
#include "service/Service.h"

namespace lenslab {

namespace {

// The token from --token-file, made and printed (this once only) when the file is new.
std::string loadToken(const std::string& tokenFile) {
    if (tokenFile.empty()) return "";
    bool created = false;
    const std::string token = loadOrCreateToken(tokenFile, created);
    if (created)
        std::cout << "lenslab serve: new API token (kept in " << tokenFile
                  << "; send it as 'Authorization: Bearer TOKEN'): " << token << std::endl;
    return token;
}

}  // namespace

int serveUntilStopped(ServiceConfig config, std::unique_ptr<JobRenderer> renderer) {
    config.access.token = loadToken(config.access.tokenFile);
    // A client that hangs up mid-response must not end the process.
    ::signal(SIGPIPE, SIG_IGN);
    // SIGINT and SIGTERM are taken by sigwait below; blocked before any thread starts so that no
    // other thread receives them.
    sigset_t stopSignals;
    sigemptyset(&stopSignals);
    sigaddset(&stopSignals, SIGINT);
    sigaddset(&stopSignals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
    // glibc gives each thread that meets a busy arena a new one, up to 8 per core. The 32 HTTP
    // workers drawing diagrams then spread the cache's PNGs and the drawings' large buffers over
    // 16 arenas, each keeping its own free holes, and resident memory crept up under steady load
    // (bench/server/RESULTS.md, soak). Two arenas reuse those holes; set before any thread starts.
    ::mallopt(M_ARENA_MAX, 2);
    // glibc raises its mmap threshold to the largest block freed (up to 32 MB): after the first
    // large diagram readback or image, such buffers came from the arenas, whose free holes stayed
    // resident (issue 23: 1.7 GB under distinct-diagram reads). A fixed threshold keeps every large
    // buffer in its own mapping, returned to the system when freed. 1 MiB: at 256 KiB the mapping
    // and faulting cost a third of the distinct-size diagram rate, at 4 MiB memory still climbed
    // (bench/README.md, issue 23).
    ::mallopt(M_MMAP_THRESHOLD, 1 << 20);

    Service service(config, std::move(renderer));
    const int port = service.start();
    std::cout << "lenslab serve: listening on http://" << config.host << ":" << port << "/ (data: " << config.dataDir
              << ")" << std::endl;
    int received = 0;
    sigwait(&stopSignals, &received);
    std::cout << "lenslab serve: stopping (signal " << received << ")" << std::endl;
    service.stop();
    return 0;
}

int runServeCommand(const std::vector<std::string>& args) {
    const auto config = parseServeOptions(args);
    if (!config) return 0;
    if (config->mpiHostfile.empty())
        return serveUntilStopped(*config, std::make_unique<EngineRenderer>(config->limits.threadsPerRender));
    MpiLaunch launch;
    launch.hostfile = config->mpiHostfile;
    launch.processes = config->mpiProcesses;
    launch.threadsPerWorker = config->limits.threadsPerRender;
    launch.scratchDir = (std::filesystem::path(config->dataDir) / "mpi").string();
    return serveUntilStopped(*config, std::make_unique<MpiRenderer>(launch));
}

}  // namespace lenslab
