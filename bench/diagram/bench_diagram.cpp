// Diagram latency for 1200x600 (dgauss.50mm, overlay): layout + draw + read-back + text + PNG
// encode per backend on a warm thread, a thread's first (cold) context, and the parts.
// Results: bench/diagram/RESULTS.md.
#include <benchmark/benchmark.h>

#include "DiagramBackend.h"
#include "DiagramPicture.h"
#include "DiagramStyle.h"
#include "GlCanvas.h"
#include "settings/LensAnalysis.h"
#include "LensDiagram.h"
#include "PngCodec.h"

namespace lenslab {
namespace {

const LensSystem& benchLens() {
    static const LensSystem lens = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    return lens;
}

DiagramOptions benchOptions(DiagramBackendKind backend) {
    DiagramOptions o;
    o.mode = DiagramMode::Overlay;
    o.backend = backend;
    return o;
}

void BM_DiagramPng(benchmark::State& state, DiagramBackendKind backend) {
    const DiagramOptions options = benchOptions(backend);
    for (auto _ : state) benchmark::DoNotOptimize(drawLensDiagramPng(benchLens(), options));
}
BENCHMARK_CAPTURE(BM_DiagramPng, osmesa, DiagramBackendKind::OSMesa)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DiagramPng, egl, DiagramBackendKind::EGL)->Unit(benchmark::kMillisecond)->UseRealTime();

// A thread's first diagram: a fresh context, its shaders compiled, one picture drawn and read back.
void BM_ColdContextAndDraw(benchmark::State& state, DiagramBackendKind backend) {
    const DiagramOptions options = benchOptions(backend);
    const DiagramPicture picture =
        composeDiagram(analyzeLens(benchLens(), options.lens), "dgauss", options);
    for (auto _ : state) {
        const auto context = createDiagramBackend(backend);
        GlCanvas canvas;
        benchmark::DoNotOptimize(canvas.rasterise(picture.shapes, picture.width, picture.height, diagram_style::kBackground));
    }
}
BENCHMARK_CAPTURE(BM_ColdContextAndDraw, osmesa, DiagramBackendKind::OSMesa)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ColdContextAndDraw, egl, DiagramBackendKind::EGL)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AnalysisAndLayout(benchmark::State& state) {
    const DiagramOptions options = benchOptions(DiagramBackendKind::OSMesa);
    for (auto _ : state)
        benchmark::DoNotOptimize(composeDiagram(analyzeLens(benchLens(), options.lens), "dgauss", options));
}
BENCHMARK(BM_AnalysisAndLayout)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RasteriseOnWarmContext(benchmark::State& state, DiagramBackendKind backend) {
    const DiagramOptions options = benchOptions(backend);
    const DiagramPicture picture =
        composeDiagram(analyzeLens(benchLens(), options.lens), "dgauss", options);
    const auto context = createDiagramBackend(backend);
    GlCanvas canvas;
    for (auto _ : state)
        benchmark::DoNotOptimize(canvas.rasterise(picture.shapes, picture.width, picture.height, diagram_style::kBackground));
}
BENCHMARK_CAPTURE(BM_RasteriseOnWarmContext, osmesa, DiagramBackendKind::OSMesa)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_RasteriseOnWarmContext, egl, DiagramBackendKind::EGL)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TextAndPng(benchmark::State& state) {
    const DiagramOptions options = benchOptions(DiagramBackendKind::OSMesa);
    const DiagramPicture picture =
        composeDiagram(analyzeLens(benchLens(), options.lens), "dgauss", options);
    const std::vector<std::uint8_t> blank(static_cast<std::size_t>(picture.width) * picture.height * 4, 255);
    for (auto _ : state) {
        std::vector<std::uint8_t> pixels = blank;
        drawTextLabels(pixels, picture.width, picture.height, picture.labels, diagram_style::kBackground);
        benchmark::DoNotOptimize(encodePngRgba8(picture.width, picture.height, pixels.data()));
    }
}
BENCHMARK(BM_TextAndPng)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace lenslab
