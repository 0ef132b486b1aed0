// The lens's share of a frame, as CPU ratios measured in one run: scenes/pbrt-v3-dgauss50.pbrt
// (400x400, 16 spp, dgauss.50mm at a 10 mm stop) through the exact lens, the thick lens and a
// perspective camera of the same field of view, interleaved round by round so that load from
// other processes falls on all three alike; then the exact and perspective frames on 1 thread.
// CPU is user + system time of this process (getrusage), setup included.
//   frame_cpu_ratios [rounds=3] [size=400] [spp=16]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "settings/LensAnalysis.h"
#include "ProcessCpuTime.h"
#include "Render.h"

namespace {

struct Cost {
    double cpu = 0, wall = 0;
};

Cost timedRender(const lenslab::RenderSettings& s) {
    const double cpu0 = lenslab::bench::processCpuSeconds();
    const auto wall0 = std::chrono::steady_clock::now();
    lenslab::renderScene(s);
    return {lenslab::bench::processCpuSeconds() - cpu0, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count()};
}

// The scene with its realistic camera replaced by a perspective one seeing the same square film
// (pbrt's fov spans the shorter side) from the lens's rear principal plane; written to /tmp.
std::string perspectiveScene(const std::string& scenePath) {
    using namespace lenslab;
    std::ifstream in(scenePath);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const LensAnalysis a = analyzeLens(loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"),
                                       std::nullopt, 5500);
    const double halfSide = 0.5 * 35 / std::sqrt(2.0);
    const double fov = 2 * std::atan(halfSide / (a.firstOrder.zPPrime - a.focus.imageZExact)) * 180 / M_PI;
    const std::size_t cam = s.find("Camera \"realistic\""), film = s.find("Film ");
    s.replace(cam, film - cam, "Camera \"perspective\" \"float fov\" " + std::to_string(fov) + "\n");
    const std::string include = "Include \"world/";
    s.replace(s.find(include), include.size(), "Include \"" + std::string(LENSLAB_SOURCE_DIR) + "/scenes/world/");
    const std::string path = (std::filesystem::temp_directory_path() / "frame_cpu_ratios_perspective.pbrt").string();
    std::ofstream(path) << s;
    return path;
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::stoi(argv[1]) : 3, size = argc > 2 ? std::stoi(argv[2]) : 400,
              spp = argc > 3 ? std::stoi(argv[3]) : 16;
    const std::string scene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/pbrt-v3-dgauss50.pbrt";
    const auto settings = [&](const std::string& path, const char* mode, int threads) {
        lenslab::RenderSettings s;
        s.scenePath = path;
        if (mode) s.camera.mode = mode;
        s.width = s.height = size;
        s.spp = spp;
        s.threads = threads;
        return s;
    };
    const std::string perspective = perspectiveScene(scene);
    const std::vector<std::pair<std::string, lenslab::RenderSettings>> runs = {
        {"perspective", settings(perspective, nullptr, 2)},
        {"exact", settings(scene, "exact", 2)},
        {"thick", settings(scene, "thick", 2)},
        {"exact, 1 thread", settings(scene, "exact", 1)},
        {"perspective, 1 thread", settings(perspective, nullptr, 1)}};
    std::map<std::string, std::vector<Cost>> costs;
    for (int r = 0; r < rounds; ++r)
        for (const auto& [name, s] : runs) costs[name].push_back(timedRender(s));
    const auto best = [&](const std::string& name, double Cost::*field) {
        double b = 1e300;
        for (const Cost& c : costs[name]) b = std::min(b, c.*field);
        return b;
    };
    std::printf("%dx%d, %d spp, best of %d interleaved rounds\n\n", size, size, spp, rounds);
    std::printf("| camera | CPU s | CPU / perspective | wall s |\n|---|---|---|---|\n");
    const double base = best("perspective", &Cost::cpu), base1 = best("perspective, 1 thread", &Cost::cpu);
    for (const auto& [name, s] : runs) {
        const double cpu = best(name, &Cost::cpu);
        std::printf("| %s | %.3f | %.3f | %.3f |\n", name.c_str(), cpu,
                    cpu / (name.find("1 thread") == std::string::npos ? base : base1), best(name, &Cost::wall));
    }
    return 0;
}
