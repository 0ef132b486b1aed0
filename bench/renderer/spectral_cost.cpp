// What a spectral frame costs and how noisy it is against the RGB frame through the same
// dispersive lens, measured in one run (the frames interleaved round by round, so that load from
// other processes falls on all alike; best of the rounds, CPU = user + system, setup included).
//
// Noise, per channel: the RMS over the pixels of each pixel minus the mean of its 5 x 5
// neighbourhood, over the channel's mean (a smooth image has next to none of its own), on
// bench/renderer/scenes/grey-wall.pbrt (a grey wall lit by a small light) through the Sony 55 mm.
// At equal time it is scaled by sqrt(CPU / RGB's CPU): variance goes as 1 / samples. Spectral with
// 1 wavelength per sample is the film before hero wavelengths; the others share each sample's
// scene path (docs/spectral.md).
//   spectral_cost [rounds=2] [spp=16] [wavelengths=1,2,4,8]
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "ProcessCpuTime.h"
#include "Render.h"

namespace {

struct Variant {
    std::string name;
    bool spectral = false;
    int wavelengths = 1;
};

struct Measured {
    double cpu = 1e300;
    lenslab::Image image;
    double blocked = 0;  // share of camera rays the lens blocked
};

// Per channel: RMS of (pixel - its 5 x 5 mean) over the channel mean, away from the border.
std::vector<double> relativeNoise(const lenslab::Image& im) {
    std::vector<double> noise(3);
    for (int c = 0; c < 3; ++c) {
        const auto at = [&](int x, int y) { return double(im.rgb[3 * (std::size_t(y) * im.width + x) + c]); };
        double sum2 = 0, level = 0;
        int n = 0;
        for (int y = 2; y < im.height - 2; ++y)
            for (int x = 2; x < im.width - 2; ++x) {
                double mean = 0;
                for (int j = -2; j <= 2; ++j)
                    for (int i = -2; i <= 2; ++i) mean += at(x + i, y + j) / 25;
                sum2 += (at(x, y) - mean) * (at(x, y) - mean);
                level += at(x, y);
                ++n;
            }
        noise[c] = std::sqrt(sum2 / n) / (level / n);
    }
    return noise;
}

std::vector<int> parseList(const std::string& s) {
    std::vector<int> v;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');) v.push_back(std::stoi(item));
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::stoi(argv[1]) : 2, spp = argc > 2 ? std::stoi(argv[2]) : 16;
    const std::vector<int> counts = parseList(argc > 3 ? argv[3] : "1,2,4,8");
    const std::string root = LENSLAB_SOURCE_DIR;
    std::vector<Variant> variants = {{"RGB", false, 1}};
    for (int w : counts) variants.push_back({"spectral, " + std::to_string(w) + " per sample", true, w});
    std::vector<Measured> results(variants.size());
    for (int r = 0; r < rounds; ++r)
        for (std::size_t v = 0; v < variants.size(); ++v) {
            lenslab::RenderSettings s;
            s.scenePath = root + "/bench/renderer/scenes/grey-wall.pbrt";
            s.camera.lensFile = root + (std::getenv("LENS") ? std::getenv("LENS") : "/lenses/us2015-0092100-ex1-55mm.zmx");
            s.camera.spectral = variants[v].spectral;
            s.wavelengthsPerSample = variants[v].wavelengths;
            s.spp = spp;
            s.threads = 2;
            const double cpu0 = lenslab::bench::processCpuSeconds();
            lenslab::RenderOutput out = lenslab::renderScene(s);
            results[v].cpu = std::min(results[v].cpu, lenslab::bench::processCpuSeconds() - cpu0);
            results[v].image = std::move(out.image);
            results[v].blocked = double(out.stats.blockedCameraRays) / double(out.stats.cameraRays);
        }
    std::printf("grey wall through the Sony 55 mm, 240 x 160, %d spp, 2 threads, best of %d interleaved rounds\n\n",
                spp, rounds);
    std::printf("| film | CPU s | CPU / RGB | camera rays blocked | noise R G B | at RGB's CPU | against RGB's noise |\n"
                "|---|---|---|---|---|---|---|\n");
    const std::vector<double> rgbNoise = relativeNoise(results[0].image);
    for (std::size_t v = 0; v < variants.size(); ++v) {
        const std::vector<double> n = relativeNoise(results[v].image);
        const double ratio = results[v].cpu / results[0].cpu, scale = std::sqrt(ratio);
        std::printf("| %s | %.2f | %.2f | %.1f%% | %.4f %.4f %.4f | %.4f %.4f %.4f | %.2f %.2f %.2f |\n",
                    variants[v].name.c_str(), results[v].cpu, ratio, 100 * results[v].blocked, n[0], n[1], n[2], n[0] * scale, n[1] * scale, n[2] * scale,
                    n[0] * scale / rgbNoise[0], n[1] * scale / rgbNoise[1], n[2] * scale / rgbNoise[2]);
    }
    return 0;
}
