// Exact tracing throughput: rays from the film of dgauss.50mm (focused at infinity, widest stop)
// through points spread uniformly over the exit pupil, film to scene, one thread.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <random>

#include "settings/LensAnalysis.h"
#include "trace/RayBatch.h"

using namespace lenslab;

namespace {

constexpr std::size_t kRays = 1 << 16;

struct Workload {
    LensSystem lens;
    RayBatch rays;
};

const Workload& workload() {
    static const Workload w = [] {
        Workload w;
        const LensAnalysis a = analyzeLens(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat"), std::nullopt,
                                           std::numeric_limits<double>::infinity());
        w.lens = a.lens;
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<double> u(0, 1);
        const double filmHalfDiagonal = 21.6;  // 36 x 24 mm film
        const double pupilRadius = 0.5 * a.pupils.exit.diameter;
        w.rays.resize(kRays);
        for (std::size_t i = 0; i < kRays; ++i) {
            const double fr = filmHalfDiagonal * std::sqrt(u(rng)), fa = 2 * M_PI * u(rng);
            const double pr = pupilRadius * std::sqrt(u(rng)), pa = 2 * M_PI * u(rng);
            const Vec3 film{fr * std::cos(fa), fr * std::sin(fa), a.focus.imageZExact};
            const Vec3 pupil{pr * std::cos(pa), pr * std::sin(pa), a.pupils.exit.z};
            w.rays.set(i, {film, normalize(pupil - film)});
        }
        return w;
    }();
    return w;
}

void ScalarTrace(benchmark::State& state) {
    const Workload& w = workload();
    std::size_t passed = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < kRays; ++i) {
            const TraceResult r = traceRay(w.lens, w.rays.get(i), TraceDirection::FilmToScene);
            passed += r.ok();
            benchmark::DoNotOptimize(r);
        }
    }
    state.SetItemsProcessed(state.iterations() * kRays);
    state.counters["passed"] = static_cast<double>(passed) / (state.iterations() * kRays);
}

void BatchTrace(benchmark::State& state) {
    const Workload& w = workload();
    RayBatch batch;
    std::size_t passed = 0;
    for (auto _ : state) {
        state.PauseTiming();
        batch = w.rays;
        state.ResumeTiming();
        traceBatch(w.lens, batch, TraceDirection::FilmToScene);
        benchmark::ClobberMemory();
        for (BlockReason b : batch.blocked) passed += b == BlockReason::None;
    }
    state.SetItemsProcessed(state.iterations() * kRays);
    state.counters["passed"] = static_cast<double>(passed) / (state.iterations() * kRays);
}

}  // namespace

BENCHMARK(ScalarTrace)->Unit(benchmark::kMillisecond);
BENCHMARK(BatchTrace)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
