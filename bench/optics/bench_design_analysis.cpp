// The lens designer's analysis of dgauss.50mm at its widest stop, focused at infinity: 3 fields
// (0, 0.7, 1 of the largest) x 3 wavelengths (F, d, C), the defaults of `lenslab analyze`. The
// whole analysis, and its per-field part alone (spots, fans, wavefronts, MTF) as the live editor
// would call it.
#include <benchmark/benchmark.h>

#include "analysis/LensDesignAnalysis.h"

using namespace lenslab;

namespace {

const LensSystem& lens() {
    static const LensSystem l = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat");
    return l;
}

void wholeAnalysis(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(analyzeLensDesign(lens(), DesignAnalysisInputs{}));
}
BENCHMARK(wholeAnalysis)->Unit(benchmark::kMillisecond);

// The curves (field curvature, distortion, illumination) at their smallest, 2 samples: what is
// left is the first-order setup and the per-field spot, fan and MTF work.
void spotsFansAndMtf(benchmark::State& state) {
    DesignAnalysisInputs in;
    in.curveSamples = 2;
    for (auto _ : state) benchmark::DoNotOptimize(analyzeLensDesign(lens(), in));
}
BENCHMARK(spotsFansAndMtf)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
