// What a spectral frame costs against the RGB frame through the same dispersive lens, as CPU ratios
// measured in one run (the two interleaved round by round, so that load from other processes falls
// on both alike), and the colour noise of each: the RMS over pixels of the chromatic part (each
// channel minus the pixel's channel mean) of the difference of two seeds, over sqrt 2. Noise at
// equal time scales the spectral noise by sqrt(CPU ratio) (variance goes as 1 / samples).
//   spectral_cost [rounds=2] [width=200] [spp=16]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ProcessCpuTime.h"
#include "Render.h"

namespace {

struct Case {
    std::string name, scene, lens;
};

double colourNoise(const lenslab::Image& a, const lenslab::Image& b) {
    double sum = 0;
    const std::size_t pixels = a.rgb.size() / 3;
    for (std::size_t p = 0; p < pixels; ++p) {
        double d[3], mean = 0;
        for (int c = 0; c < 3; ++c) mean += (d[c] = a.rgb[3 * p + c] - b.rgb[3 * p + c]) / 3;
        for (int c = 0; c < 3; ++c) sum += (d[c] - mean) * (d[c] - mean);
    }
    return std::sqrt(sum / (3.0 * pixels)) / std::sqrt(2.0);
}

double meanLevel(const lenslab::Image& a) {
    double s = 0;
    for (float v : a.rgb) s += v;
    return s / a.rgb.size();
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::stoi(argv[1]) : 2, width = argc > 2 ? std::stoi(argv[2]) : 200,
              spp = argc > 3 ? std::stoi(argv[3]) : 16;
    const std::string root = LENSLAB_SOURCE_DIR;
    const std::vector<Case> cases = {
        {"shared-dgauss, dgauss-glass", root + "/scenes/shared-dgauss.pbrt", root + "/lenses/dgauss-glass.dat"},
        {"shared-dgauss, Sony 55 mm (.zmx)", root + "/scenes/shared-dgauss.pbrt", root + "/lenses/us2015-0092100-ex1-55mm.zmx"},
        {"lateral-colour-chart, dgauss-glass", root + "/scenes/lateral-colour-chart.pbrt", root + "/lenses/dgauss-glass.dat"},
    };
    std::printf("%d pixels wide, %d spp, 2 threads, best of %d interleaved rounds; CPU = user + system, setup included\n\n",
                width, spp, rounds);
    std::printf("| scene, lens | RGB CPU s | spectral CPU s | spectral / RGB | colour noise RGB | spectral | spectral at equal time | mean level | blocked RGB / spectral |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const Case& c : cases) {
        const auto settings = [&](bool spectral, std::uint64_t seed) {
            lenslab::RenderSettings s;
            s.scenePath = c.scene;
            s.camera.lensFile = c.lens;
            s.camera.spectral = spectral;
            s.width = width;
            s.spp = spp;
            s.threads = 2;
            s.seed = seed;
            return s;
        };
        double best[2] = {1e300, 1e300}, blocked[2] = {0, 0};
        lenslab::Image first[2];
        for (int r = 0; r < rounds; ++r)
            for (int spectral = 0; spectral < 2; ++spectral) {
                const double cpu0 = lenslab::bench::processCpuSeconds();
                lenslab::RenderOutput out = lenslab::renderScene(settings(spectral, 1));
                best[spectral] = std::min(best[spectral], lenslab::bench::processCpuSeconds() - cpu0);
                blocked[spectral] = double(out.stats.blockedCameraRays) / double(out.stats.cameraRays);
                first[spectral] = std::move(out.image);
            }
        double noise[2];
        for (int spectral = 0; spectral < 2; ++spectral)
            noise[spectral] = colourNoise(first[spectral], lenslab::renderScene(settings(spectral, 2)).image);
        const double ratio = best[1] / best[0];
        std::printf("| %s | %.3f | %.3f | %.3f | %.5f | %.5f | %.5f | %.4f | %.2f%% / %.2f%% |\n", c.name.c_str(), best[0],
                    best[1], ratio, noise[0], noise[1], noise[1] * std::sqrt(ratio), meanLevel(first[0]), 100 * blocked[0],
                    100 * blocked[1]);
        std::fflush(stdout);
    }
    return 0;
}
