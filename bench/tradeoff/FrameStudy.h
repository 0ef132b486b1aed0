#pragma once
// Whole frames of the shared world (scenes/shared-dgauss.pbrt with the study's lens, stop, focus
// and 36 x 24 mm film put in by overrides) in one mode, timed, and their error against a reference.
#include <string>

#include "Render.h"
#include "TradeoffCases.h"

namespace lenslab::tradeoff {

struct TimedFrame {
    Image image;
    // CPU seconds (user + system, all threads) of the whole render, setup included (scene, camera:
    // bounds and error map, BVH): on a shared machine far steadier than wall time.
    double cpuSeconds = 0;
    std::string split;  // which film radii the thick lens drew
    double seconds() const { return cpuSeconds; }
};

TimedFrame renderFrame(const LensCase& lens, const StopCase& stop, const std::string& mode, int width, int height, int spp,
                  int threads = 2);

// RMS over pixels and channels of (image - reference), divided by the reference's mean value.
double relativeRmse(const Image& image, const Image& reference);

}  // namespace lenslab::tradeoff
