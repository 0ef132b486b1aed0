// Renders the shared world (scenes/shared-*.pbrt and the pbrt-v3-style dgauss.50mm scene) at
// 400x400, 16 spp on 2 threads and prints a Markdown table for bench/renderer/RESULTS.md: wall
// time per frame, camera setup time (lens analysis, focus, exit-pupil bounds), rays per second and
// the fraction of camera rays the lens blocks.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <string>

#include "cameras/RealisticCamera.h"
#include "Render.h"

namespace {

double cameraSetupSeconds(const lenslab::RenderOutput& out) {
    using namespace lenslab;
    RealisticParams p = realisticParams(out.metadata.at("lensFile"), std::stod(out.metadata.at("fstop")),
                                        std::stod(out.metadata.at("focusDistanceMm")));
    p.filmDiagonalMm = std::stod(out.metadata.at("filmDiagonalMm"));
    const auto start = std::chrono::steady_clock::now();
    RealisticCamera camera(p, {}, 400, 400, 0.5);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const int threads = argc > 1 ? std::stoi(argv[1]) : 2;
    const std::string dir = std::string(LENSLAB_SOURCE_DIR) + "/scenes/";
    std::printf("| scene | lens | wall s/frame | CPU s/frame | setup s (scene+camera+BVH) | camera setup s | render s | Mrays/s | blocked camera rays |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const char* name : {"shared-dgauss", "shared-wide", "shared-telephoto", "shared-fisheye", "pbrt-v3-dgauss50"}) {
        lenslab::RenderSettings s;
        s.scenePath = dir + name + ".pbrt";
        s.width = 400;
        s.height = 400;
        s.spp = 16;
        s.threads = threads;
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpuStart = std::clock();  // process CPU time: the machine is shared
        const lenslab::RenderOutput out = lenslab::renderScene(s);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        const auto& st = out.stats;
        const std::string lens = out.metadata.at("lensFile");
        std::printf("| %s | %s | %.2f | %.2f | %.3f | %.3f | %.2f | %.2f | %.2f%% |\n", name, lens.substr(lens.rfind('/') + 1).c_str(),
                    wall, cpu, st.setupSeconds, cameraSetupSeconds(out), st.renderSeconds, st.raysTraced / st.renderSeconds * 1e-6,
                    100.0 * double(st.blockedCameraRays) / double(st.cameraRays));
        std::fflush(stdout);
    }
    return 0;
}
