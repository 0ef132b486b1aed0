#include "FrameStudy.h"

#include <cmath>
#include <stdexcept>

#include "settings/LensAnalysis.h"
#include "ProcessCpuTime.h"

namespace lenslab::tradeoff {

TimedFrame renderFrame(const LensCase& lens, const StopCase& stop, const std::string& mode, int width, int height, int spp,
                  int threads) {
    RenderSettings s;
    s.scenePath = std::string(LENSLAB_SOURCE_DIR) + "/scenes/shared-dgauss.pbrt";
    s.camera.lensFile = lens.path;
    // The scene names its own stop: the widest must be asked for by number.
    s.camera.fstop = Setting{stop.fstop ? *stop.fstop : analyzeLens(loadLensSystem(lens.path), std::nullopt, kFocusDistanceMm).fstop, "bench"};
    s.camera.focusDistance = Setting{kFocusDistanceMm, "bench"};
    s.camera.filmDiagonal = filmDiagonalMm();
    s.camera.mode = mode;
    s.width = width;
    s.height = height;
    s.spp = spp;
    s.threads = threads;
    const double cpu0 = bench::processCpuSeconds();
    RenderOutput out = renderScene(s);
    TimedFrame f;
    f.cpuSeconds = bench::processCpuSeconds() - cpu0;
    f.image = std::move(out.image);
    f.split = out.metadata.at("lensModelByFilmRadius");
    return f;
}

double relativeRmse(const Image& image, const Image& reference) {
    if (image.rgb.size() != reference.rgb.size() || reference.rgb.empty())
        throw std::invalid_argument("relativeRmse: images of different sizes");
    double sum = 0, mean = 0;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const double d = double(image.rgb[i]) - reference.rgb[i];
        sum += d * d;
        mean += reference.rgb[i];
    }
    const double n = double(image.rgb.size());
    return std::sqrt(sum / n) / (mean / n);
}

}  // namespace lenslab::tradeoff
