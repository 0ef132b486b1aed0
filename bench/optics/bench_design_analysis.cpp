// The lens designer's analysis at the widest stop, focused at infinity, with the defaults of
// `lenslab analyze` (docs/analysis.md): 3 fields (0, 0.7, 1 of the largest) x 3 wavelengths (F, d,
// C), spots settled over the pupil, fans, wavefronts and MTF, the four curves. dgauss.50mm (11
// surfaces, no dispersion) and the Canon 35 mm (22 surfaces, two aspheres, dispersive: the page's
// target of 150 ms of server time). The whole analysis, and its per-field part alone (the curves at
// 2 samples) as the live editor calls it. The threads are TBB's: wall time on two idle cores is the
// server's time; CPU time (user + system, in the counters) is the work.
#include <benchmark/benchmark.h>

#include <string>

#include "ProcessCpuTime.h"
#include "analysis/LensDesignAnalysis.h"
#include "analysis/RelativeIllumination.h"
#include "firstorder/FirstOrder.h"

using namespace lenslab;
using lenslab::bench::processCpuSeconds;

namespace {

const LensSystem& lens(int which) {
    static const LensSystem dgauss = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat");
    static const LensSystem canon = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us2010-0033848-ex1-35mm.zmx");
    return which == 0 ? dgauss : canon;
}

void analyse(benchmark::State& state, int curveSamples) {
    DesignAnalysisInputs in;
    in.curveSamples = curveSamples;
    const double cpu0 = processCpuSeconds();
    for (auto _ : state) benchmark::DoNotOptimize(analyzeLensDesign(lens(int(state.range(0))), in));
    state.counters["cpu_ms"] = 1e3 * (processCpuSeconds() - cpu0) / double(state.iterations());
    state.SetLabel(state.range(0) == 0 ? "dgauss.50mm" : "canon-35mm");
}

void wholeAnalysis(benchmark::State& state) { analyse(state, 16); }
BENCHMARK(wholeAnalysis)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The curves at their smallest, 2 samples: what is left is the first-order setup and the per-field
// spot, fan and MTF work.
void spotsFansAndMtf(benchmark::State& state) { analyse(state, 2); }
BENCHMARK(spotsFansAndMtf)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The analysis's relative illumination of the Canon (16 film radii, 64 x 64 grids, to the largest
// field's image height) over the half y >= 0 of each grid, as its symmetry allows (arg 0), and over
// the whole grids, the lens marked decentred (arg 1): the shortcut's gain, in one run.
void relativeIlluminationOfTheCanon(benchmark::State& state) {
    LensSystem canon = lens(1);
    canon.decentred = state.range(0) == 1;
    const FirstOrder fo = computeFirstOrder(canon);
    const double cpu0 = processCpuSeconds();
    for (auto _ : state) benchmark::DoNotOptimize(relativeIllumination(canon, fo.zFPrime, 21.6, {16, 64}));
    state.counters["cpu_ms"] = 1e3 * (processCpuSeconds() - cpu0) / double(state.iterations());
    state.SetLabel(state.range(0) == 0 ? "half grids" : "whole grids");
}
BENCHMARK(relativeIlluminationOfTheCanon)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
BENCHMARK_MAIN();
