// Time per camera ray of each lens model, for every lens, stop and field position of the study
// (TradeoffCases.h), one thread:
//   camera/accurate     RealisticCamera::generateRays, exact trace, in the renderer's batches of 256
//   camera/accurate16   the same in batches of one pixel's 16 samples
//   camera/approximate  the same through the thick lens
//   lens/double         the exact lens trace alone (traceRay), rays aimed by the exit-pupil bounds
//   lens/batched        the same trace as structure-of-arrays batches of 16 and of 256 (traceBatch)
//   lens/float          the same trace carried out in float (traceRayT<float>)
//   lens/thick          the thick-lens trace alone (traceThick)
// Items/s are camera rays per second; blocked rays count (they cost the trace up to the block).
#include <benchmark/benchmark.h>

#include <memory>

#include "trace/ExactTrace.h"
#include "FieldSamples.h"
#include "trace/RayBatch.h"
#include "cameras/RealisticCamera.h"
#include "sampling/Sampling.h"

using namespace lenslab;
using namespace lenslab::tradeoff;

namespace {

constexpr int kRays = 4096;
constexpr int kPixelBatch = 16;  // samples per generateRays call, as a pixel's at 16 spp
constexpr int kRunBatch = 256;   // as the renderer calls it: a run of 16 pixels at 16 spp

struct Workload {
    std::shared_ptr<RealisticCamera> accurate, approximate;
    std::vector<CameraSample> samples;
    std::vector<Ray> exactRays, thickRays;  // aimed from the film, ready for the lens
};

Workload makeWorkload(const LensCase& lens, const StopCase& stop, const FieldCase& field) {
    Workload w;
    RealisticParams p = realisticParams(lens.path, stop.fstop, kFocusDistanceMm);
    p.filmDiagonalMm = filmDiagonalMm();
    w.accurate = std::make_shared<RealisticCamera>(p, Transform{}, kFrameWidth, kFrameHeight, 0.5);
    p.mode = LensMode::Thick;
    w.approximate = std::make_shared<RealisticCamera>(p, Transform{}, kFrameWidth, kFrameHeight, 0.5);
    w.samples = fieldSamples(field.fraction, kFrameWidth, kFrameHeight, kRays);
    const Pupil& xp = w.approximate->analysis().pupils.exit;
    for (const CameraSample& s : w.samples) {
        double fx, fy;
        w.accurate->filmPoint(s.rasterX, s.rasterY, fx, fy);
        const Vec3 exactFrom{fx, fy, w.accurate->filmZ()};
        const PupilSample aim = sampleExitPupil(w.accurate->pupilBounds(), fx, fy, s.u1, s.u2);
        w.exactRays.push_back({exactFrom, normalize(aim.point - exactFrom)});
        float dx, dy;
        concentricDisk(s.u1, s.u2, dx, dy);
        const Vec3 thickFrom{fx, fy, w.approximate->filmZ()};
        w.thickRays.push_back({thickFrom, normalize(Vec3{0.5 * xp.diameter * dx, 0.5 * xp.diameter * dy, xp.z} - thickFrom)});
    }
    return w;
}

void cameraRays(benchmark::State& state, std::shared_ptr<const Workload> w, bool approximate, int batch) {
    const RealisticCamera& camera = approximate ? *w->approximate : *w->accurate;
    std::vector<CameraRay> out(batch);
    for (auto _ : state) {
        for (int i = 0; i < kRays; i += batch) camera.generateRays(&w->samples[i], batch, out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * kRays);
}

void batchedTrace(benchmark::State& state, std::shared_ptr<const Workload> w, int size) {
    const LensSystem& lens = w->accurate->analysis().lens;
    RayBatch batch;
    batch.resize(size);
    for (auto _ : state)
        for (int i = 0; i < kRays; i += size) {
            for (int k = 0; k < size; ++k) batch.set(k, w->exactRays[i + k]);
            traceBatch(lens, batch, TraceDirection::FilmToScene);
            benchmark::DoNotOptimize(batch.ox.data());
        }
    state.SetItemsProcessed(state.iterations() * kRays);
}

template <class Scalar>
void exactTrace(benchmark::State& state, std::shared_ptr<const Workload> w) {
    const LensSystem& lens = w->accurate->analysis().lens;
    for (auto _ : state)
        for (const Ray& r : w->exactRays) benchmark::DoNotOptimize(traceRayT<Scalar>(lens, r, TraceDirection::FilmToScene));
    state.SetItemsProcessed(state.iterations() * kRays);
}

void thickTrace(benchmark::State& state, std::shared_ptr<const Workload> w) {
    const ThickLens& thick = w->approximate->analysis().thick;
    for (auto _ : state)
        for (const Ray& r : w->thickRays) benchmark::DoNotOptimize(traceThick(thick, r, TraceDirection::FilmToScene));
    state.SetItemsProcessed(state.iterations() * kRays);
}

}  // namespace

int main(int argc, char** argv) {
    for (const LensCase& lens : lensCases())
        for (const StopCase& stop : stopCases())
            for (const FieldCase& field : fieldCases()) {
                const auto w = std::make_shared<const Workload>(makeWorkload(lens, stop, field));
                const std::string name = lens.name + "/" + stop.label + "/" + field.label;
                const double minTime = 0.05;
                benchmark::RegisterBenchmark(("camera/accurate/" + name).c_str(), cameraRays, w, false, kRunBatch)->MinTime(minTime);
                benchmark::RegisterBenchmark(("camera/accurate16/" + name).c_str(), cameraRays, w, false, kPixelBatch)->MinTime(minTime);
                benchmark::RegisterBenchmark(("camera/approximate/" + name).c_str(), cameraRays, w, true, kRunBatch)->MinTime(minTime);
                benchmark::RegisterBenchmark(("lens/double/" + name).c_str(), exactTrace<double>, w)->MinTime(minTime);
                benchmark::RegisterBenchmark(("lens/batched16/" + name).c_str(), batchedTrace, w, kPixelBatch)->MinTime(minTime);
                benchmark::RegisterBenchmark(("lens/batched/" + name).c_str(), batchedTrace, w, kRunBatch)->MinTime(minTime);
                benchmark::RegisterBenchmark(("lens/float/" + name).c_str(), exactTrace<float>, w)->MinTime(minTime);
                benchmark::RegisterBenchmark(("lens/thick/" + name).c_str(), thickTrace, w)->MinTime(minTime);
            }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
