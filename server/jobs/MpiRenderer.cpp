#include "jobs/MpiRenderer.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "storage/AtomicFile.h"
#include "jobs/ChildProcess.h"

namespace lenslab {

namespace {

namespace fs = std::filesystem;

std::string exactNumber(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

// mpirun's path: as given when it names a file, else the first match on PATH (posix_spawn does not search).
std::string findProgram(const std::string& name) {
    if (name.find('/') != std::string::npos) return name;
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    throw std::runtime_error("cannot find '" + name + "' on PATH (install openmpi-bin)");
}

// The last lines of the child's stderr, for the job's error message.
std::string tail(const std::string& path, std::size_t maxChars) {
    std::string text;
    try {
        text = readWholeFile(path);
    } catch (const std::exception&) {
        return "";
    }
    return text.size() > maxChars ? "..." + text.substr(text.size() - maxChars) : text;
}

}  // namespace

MpiRenderer::MpiRenderer(MpiLaunch launch) : launch_(std::move(launch)) {
    launch_.mpirun = findProgram(launch_.mpirun);
    lenslabBinary_ = fs::read_symlink("/proc/self/exe").string();
    fs::create_directories(launch_.scratchDir);
}

RenderedImages MpiRenderer::render(const RenderJobInput& job, const TileCallback& onTile, const std::atomic<bool>& cancel) {
    static std::atomic<unsigned> counter{0};
    const std::string stem =
        (fs::path(launch_.scratchDir) / ("job-" + std::to_string(::getpid()) + "-" + std::to_string(counter++))).string();
    const std::string exr = stem + ".exr", png = stem + ".png", log = stem + ".log";
    const RenderRequest& r = job.request;
    std::vector<std::string> argv{launch_.mpirun};
    if (::geteuid() == 0) argv.push_back("--allow-run-as-root");
    argv.insert(argv.end(), {"--hostfile", launch_.hostfile, "-np", std::to_string(launch_.processes), lenslabBinary_,
                             "render", job.scenePath, "--mpi", "--progress-json", "--quiet", "--mode", r.mode, "--spp", std::to_string(r.spp), "--width", std::to_string(r.width),
                             "--height", std::to_string(r.height), "-o", exr, "-o", png});
    if (!job.lensPath.empty()) argv.insert(argv.end(), {"--lens", job.lensPath, "--layout", layoutName(job.lensLayout)});
    if (launch_.threadsPerWorker > 0) argv.insert(argv.end(), {"--threads", std::to_string(launch_.threadsPerWorker)});
    if (r.fstop) argv.insert(argv.end(), {"--fstop", exactNumber(*r.fstop)});
    if (r.focusDistance) argv.insert(argv.end(), {"--focus", exactNumber(*r.focusDistance)});
    if (r.filmDiagonal) argv.insert(argv.end(), {"--filmdiag", exactNumber(*r.filmDiagonal)});
    if (r.spectral) argv.insert(argv.end(), {"--spectral", *r.spectral ? "on" : "off"});
    if (r.ghosts) argv.insert(argv.end(), {"--ghosts", *r.ghosts});
    if (r.ghostModel) argv.insert(argv.end(), {"--ghost-model", *r.ghostModel});

    struct Cleanup {
        std::vector<std::string> paths;
        ~Cleanup() {
            for (const auto& p : paths) std::remove(p.c_str());
        }
    } cleanup{{exr, png, log}};

    ChildProcess child(argv, log);
    Image black;
    black.width = r.width;
    black.height = r.height;
    black.rgb.assign(std::size_t(r.width) * r.height * 3, 0.0f);
    nlohmann::json finished;
    while (!child.finished()) {
        if (cancel) {
            child.killGroup(std::chrono::seconds(5));
            throw RenderCancelled();
        }
        const auto line = child.readLine(std::chrono::milliseconds(100));
        if (!line) continue;
        const nlohmann::json j = nlohmann::json::parse(*line, nullptr, false);
        if (!j.is_object()) continue;
        if (j.contains("finished")) {
            finished = j;
        } else if (onTile && j.contains("tilesDone")) {
            const TileUpdate u{j.value("x0", 0), j.value("y0", 0), j.value("x1", 0), j.value("y1", 0),
                               j.value("tilesDone", 0), j.value("tilesTotal", 0)};
            onTile(u, black);
        }
    }
    const int status = child.wait();
    if (cancel) throw RenderCancelled();
    if (status != 0 || finished.is_null())
        throw std::runtime_error("the MPI render (mpirun -np " + std::to_string(launch_.processes) + ") failed with status " +
                                 std::to_string(status) + ": " + tail(log, 2000));
    RenderedImages images;
    const std::string exrBytes = readWholeFile(exr), pngBytes = readWholeFile(png);
    images.exr.assign(exrBytes.begin(), exrBytes.end());
    images.png.assign(pngBytes.begin(), pngBytes.end());
    images.stats = {{"setup_s", finished.value("setupSeconds", 0.0)},
                    {"render_s", finished.value("renderSeconds", 0.0)},
                    {"camera_rays", finished.value("cameraRays", 0ULL)},
                    {"blocked_camera_rays", finished.value("blockedCameraRays", 0ULL)},
                    {"rays_traced", finished.value("raysTraced", 0ULL)},
                    {"flare_paths", finished.value("flarePaths", 0)},
                    {"flare_rays", finished.value("flareRays", 0ULL)},
                    {"flare_s", finished.value("flareSeconds", 0.0)},
                    {"mpi_processes", launch_.processes}};
    images.warnings = finished.value("warnings", std::vector<std::string>{});
    return images;
}

std::vector<std::uint8_t> MpiRenderer::encodePreview(const Image& partial) const { return encodePng(partial); }

}  // namespace lenslab
