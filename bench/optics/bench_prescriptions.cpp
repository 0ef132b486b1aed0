// Real prescriptions: exact rays through even aspheres against their all-spherical twins (film to
// scene, batch, one thread), and reading plus analysing a 30-surface Zemax file.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "settings/LensAnalysis.h"
#include "trace/RayBatch.h"

using namespace lenslab;

namespace {

constexpr std::size_t kRays = 1 << 16;

// Rays from a 36 x 24 mm film through points spread over the exit pupil, for the lens at infinity.
RayBatch filmRays(const LensAnalysis& a) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    const double filmHalfDiagonal = 21.6, pupilRadius = 0.5 * a.pupils.exit.diameter;
    RayBatch rays;
    rays.resize(kRays);
    for (std::size_t i = 0; i < kRays; ++i) {
        const double fr = filmHalfDiagonal * std::sqrt(u(rng)), fa = 2 * M_PI * u(rng);
        const double pr = pupilRadius * std::sqrt(u(rng)), pa = 2 * M_PI * u(rng);
        const Vec3 film{fr * std::cos(fa), fr * std::sin(fa), a.focus.imageZExact};
        const Vec3 pupil{pr * std::cos(pa), pr * std::sin(pa), a.pupils.exit.z};
        rays.set(i, {film, normalize(pupil - film)});
    }
    return rays;
}

LensSystem withoutAspheres(LensSystem lens) {
    for (Surface& s : lens.surfaces) {
        s.conic = 0;
        s.aspheric = {};
    }
    return lens;
}

// dgauss.50mm with four surfaces made even aspheres (conic and r^4, r^6 terms of a realistic size),
// or the Sony 55 mm of US 2015/0092100 (five aspheres); the twin has the same surfaces as spheres.
LensSystem benchLens(int which, bool aspheric) {
    if (which == 0) {
        LensTable t = readLensTable(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat");
        for (int i : {0, 3, 7, 10}) {
            t.rows[i].conic = -0.3;
            t.rows[i].aspheric = {0, 2e-6, -4e-9, 0, 0, 0, 0, 0};
        }
        const LensSystem lens = buildLensSystem(t);
        return aspheric ? lens : withoutAspheres(lens);
    }
    const LensSystem lens = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us2015-0092100-ex1-55mm.zmx");
    return aspheric ? lens : withoutAspheres(lens);
}

void BatchTrace(benchmark::State& state) {
    const bool aspheric = state.range(1) != 0;
    const LensSystem built = benchLens(static_cast<int>(state.range(0)), aspheric);
    // Rays and pupils from the aspheric lens for both, so the twin traces the same rays.
    const LensAnalysis a = analyzeLens(benchLens(static_cast<int>(state.range(0)), true), 4.0, std::numeric_limits<double>::infinity());
    LensSystem lens = built;
    lens.surfaces[lens.stopIndex].apertureRadius = a.lens.stop().apertureRadius;
    const RayBatch rays = filmRays(a);
    RayBatch batch;
    std::size_t passed = 0;
    for (auto _ : state) {
        state.PauseTiming();
        batch = rays;
        state.ResumeTiming();
        traceBatch(lens, batch, TraceDirection::FilmToScene);
        benchmark::ClobberMemory();
        for (BlockReason b : batch.blocked) passed += b == BlockReason::None;
    }
    state.SetItemsProcessed(state.iterations() * kRays);
    state.counters["passed"] = static_cast<double>(passed) / (state.iterations() * kRays);
    state.SetLabel(std::string(state.range(0) == 0 ? "dgauss.50mm+4 aspheres" : "us2015-0092100 (5 aspheres)") +
                   (aspheric ? ", aspheric" : ", spherical twin"));
}

// 30 surfaces and a stop: fifteen weak N-BK7 and N-SF5 elements from the catalog, every third
// surface an even asphere, written as a .zmx.
std::string thirtySurfaceZemax() {
    std::ostringstream z;
    z << "VERS 1\nMODE SEQ\nNAME 30 surfaces\nUNIT MM X W X CM MR CPMM\nGCAT SCHOTT\n"
         "WAVM 1 0.4861327 1\nWAVM 2 0.5875618 1\nWAVM 3 0.6562725 1\nPWAV 2\n"
         "SURF 0\n  CURV 0\n  DISZ INFINITY\n";
    int n = 1;
    for (int e = 0; e < 15; ++e) {
        if (e == 7) z << "SURF " << n++ << "\n  STOP\n  CURV 0\n  DISZ 2\n  DIAM 8 0 0 0 1 \"\"\n";
        for (int side = 0; side < 2; ++side, ++n) {
            const bool asphere = n % 3 == 0;
            z << "SURF " << n << "\n  TYPE " << (asphere ? "EVENASPH" : "STANDARD") << "\n  CURV "
              << (side == 0 ? 1.0 / 300 : -1.0 / 300) << "\n  DISZ " << (side == 0 ? 2.5 : 1.0) << "\n";
            if (side == 0) z << "  GLAS " << (e % 2 ? "N-SF5" : "N-BK7") << " 0 0 1.5 40 0 0 0 0 0 0\n";
            if (asphere) z << "  PARM 2 1e-7\n  PARM 3 -2e-10\n";
            z << "  DIAM 10 0 0 0 1 \"\"\n";
        }
    }
    z << "SURF " << n << "\n  CURV 0\n  DISZ 0\n";
    return z.str();
}

void LoadAndAnalyseZemax(benchmark::State& state) {
    const std::string text = thirtySurfaceZemax();
    for (auto _ : state) {
        const LensSystem lens = buildLensSystem(parseLensTable(text, "thirty.zmx"));
        const LensAnalysis a = analyzeLens(lens, std::nullopt, std::numeric_limits<double>::infinity());
        benchmark::DoNotOptimize(a.chromatic.lateral);
    }
    state.SetLabel(std::to_string(buildLensSystem(parseLensTable(text, "thirty.zmx")).surfaces.size()) +
                   " surfaces, catalog glasses, chromatic block included");
}

}  // namespace

BENCHMARK(BatchTrace)->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(LoadAndAnalyseZemax)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
