// What lens flare costs and what the paraxial model gives up: one point light in the frame through
// dgauss.50mm (and the Sony 55 mm and the reflex lens for comparison), each frame rendered with
// ghosts off, auto with the light too dim to matter, all ghosts exact and all paraxial, interleaved
// round by round (load from other processes falls on all alike); CPU = user + system of the
// process, setup included, best of the rounds. The flare layer is the difference of a frame with
// ghosts and the same seed's frame without; the paraxial layer is compared with the exact one by
// its total light and by the correlation of 8x8-pixel block sums.
//   flare_cost [rounds=2] [width=512] [spp=16]
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ProcessCpuTime.h"
#include "Render.h"

namespace {

// A field under a dim sky with a point light 25 m ahead, up and to the left: in the frame of every
// lens below. `intensity` W/sr: 5000 lights the lens with an irradiance near 8; 1e-6 is too dim for
// auto through every lens (1e-3 is not through the reflex: its direct image, one pixel of a 500 mm
// lens, has a radiance near 110, over the threshold of 100).
std::string sceneText(const std::string& lens, double fstop, double intensity) {
    return "Scale 1000 1000 1000\nLookAt 0 1.5 0  0 1.6 10  0 1 0\n"
           "Camera \"realistic\" \"string specfile\" \"" + lens + "\" \"float fstop\" " + std::to_string(fstop) +
           " \"float focaldistance\" 20000 "
           "\"float filmdiagonal\" 43.27\nSampler \"sobol\"\nIntegrator \"path\" \"integer maxdepth\" 3\nWorldBegin\n"
           "LightSource \"infinite\" \"rgb L\" [0.12 0.16 0.26]\n"
           "LightSource \"point\" \"point from\" [-1.2 2.3 25] \"rgb I\" [" + std::to_string(intensity) + " " +
           std::to_string(intensity) + " " + std::to_string(intensity) + "]\n"
           "Material \"matte\" \"rgb Kd\" [0.3 0.28 0.2]\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-200 0 -5  200 0 -5  200 0 300  -200 0 300]\n"
           "Material \"plastic\" \"rgb Kd\" [0.4 0.3 0.25]\nTranslate 0.8 0.5 8\nShape \"sphere\" \"float radius\" 0.5\nWorldEnd\n";
}

struct Frame {
    lenslab::Image image;
    lenslab::RenderStats stats;
    double cpu = 1e300;
};

std::vector<double> layer(const lenslab::Image& with, const lenslab::Image& without) {
    std::vector<double> out(with.rgb.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int c = 0; c < 3; ++c) out[i] += with.rgb[3 * i + c] - without.rgb[3 * i + c];
    return out;
}

double blockCorrelation(const std::vector<double>& a, const std::vector<double>& b, int width, int height) {
    constexpr int kBlock = 8;
    std::vector<double> x, y;
    for (int by = 0; by + kBlock <= height; by += kBlock)
        for (int bx = 0; bx + kBlock <= width; bx += kBlock) {
            double sa = 0, sb = 0;
            for (int j = 0; j < kBlock; ++j)
                for (int i = 0; i < kBlock; ++i) sa += a[std::size_t(by + j) * width + bx + i], sb += b[std::size_t(by + j) * width + bx + i];
            x.push_back(sa);
            y.push_back(sb);
        }
    double mx = 0, my = 0, sxy = 0, sxx = 0, syy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / x.size(), my += y[i] / y.size();
    for (std::size_t i = 0; i < x.size(); ++i)
        sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx), syy += (y[i] - my) * (y[i] - my);
    return sxy / std::sqrt(sxx * syy);
}

double sum(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::stoi(argv[1]) : 2, width = argc > 2 ? std::stoi(argv[2]) : 512,
              spp = argc > 3 ? std::stoi(argv[3]) : 16;
    const std::string root = LENSLAB_SOURCE_DIR;
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lenslab-flare-cost";
    std::filesystem::create_directories(dir);
    // The Sony 55 mm wide open: main's exit-pupil bounds block every camera ray of it from f/5.6.
    struct Case {
        std::string name, lens;
        double fstop;
    };
    const std::vector<Case> cases = {{"dgauss.50mm", root + "/lenses/dgauss.50mm.dat", 8},
                                     {"Sony 55 mm", root + "/lenses/us2015-0092100-ex1-55mm.zmx", 2},
                                     {"reflex 500 mm", root + "/lenses/us4666259-ex1-reflex-500mm.zmx", 6.7021}};
    std::printf("%dx%d, %d spp, 2 threads, one point light in the frame; best of %d interleaved rounds; CPU = user + system, setup included\n\n",
                width, width, spp, rounds);
    std::printf("| lens, f-number | paths | off CPU s | auto, dim light: CPU s, same bits | exact: CPU s, over off | paraxial: CPU s, over off | paraxial light / exact | block correlation |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (const Case& c : cases) {
        const std::string bright = (dir / "bright.pbrt").string(), dim = (dir / "dim.pbrt").string();
        std::ofstream(bright) << sceneText(c.lens, c.fstop, 5000);
        std::ofstream(dim) << sceneText(c.lens, c.fstop, 1e-6);
        struct Variant {
            std::string scene, ghosts, model;
        };
        const std::vector<Variant> variants = {{bright, "off", "exact"}, {dim, "auto", "exact"}, {bright, "all", "exact"},
                                               {bright, "all", "paraxial"}, {dim, "off", "exact"}};
        std::vector<Frame> frames(variants.size());
        for (int r = 0; r < rounds; ++r)
            for (std::size_t v = 0; v < variants.size(); ++v) {
                lenslab::RenderSettings s;
                s.scenePath = variants[v].scene;
                s.width = s.height = width;
                s.spp = spp;
                s.threads = 2;
                s.camera.ghosts = variants[v].ghosts;
                s.camera.ghostModel = variants[v].model;
                const double cpu0 = lenslab::bench::processCpuSeconds();
                lenslab::RenderOutput out = lenslab::renderScene(s);
                frames[v].cpu = std::min(frames[v].cpu, lenslab::bench::processCpuSeconds() - cpu0);
                frames[v].image = std::move(out.image);
                frames[v].stats = out.stats;
            }
        const std::vector<double> exact = layer(frames[2].image, frames[0].image), paraxial = layer(frames[3].image, frames[0].image);
        const double off = frames[0].cpu;
        std::printf("| %s, f/%.3g | %d | %.3f | %.3f, %s | %.3f, %+.1f%% | %.3f, %+.1f%% | %.3f | %.3f |\n", c.name.c_str(), c.fstop,
                    frames[2].stats.flarePaths, off, frames[1].cpu, frames[1].image.rgb == frames[4].image.rgb ? "yes" : "NO",
                    frames[2].cpu, 100 * (frames[2].cpu / off - 1), frames[3].cpu, 100 * (frames[3].cpu / off - 1),
                    sum(paraxial) / sum(exact), blockCorrelation(exact, paraxial, width, width));
        std::fflush(stdout);
    }
    return 0;
}
