// Many diagrams at once from different threads, on both backends, as the server draws them.
#include <gtest/gtest.h>

#include <thread>

#include "CanvasLease.h"
#include "DiagramTestSupport.h"

namespace lenslab::test {
namespace {

TEST(DiagramConcurrency, ThreadsOnBothBackendsMatchTheSerialPicture) {
    const LensSystem lens = loadBundledLens("wide.22mm");
    DiagramOptions options;
    options.width = 600;
    options.height = 300;
    options.mode = DiagramMode::Overlay;
    const std::vector<std::uint8_t> reference = drawLensDiagramPng(lens, options);

    constexpr int kThreads = 8, kEach = 3;
    std::vector<std::vector<std::uint8_t>> results(kThreads * kEach);
    std::vector<std::string> errors(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            DiagramOptions mine = options;
            mine.backend = t % 2 == 0 ? DiagramBackendKind::OSMesa : DiagramBackendKind::EGL;
            try {
                for (int i = 0; i < kEach; ++i) results[t * kEach + i] = drawLensDiagramPng(lens, mine);
            } catch (const std::exception& e) {
                errors[t] = e.what();
            }
        });
    }
    for (auto& thread : threads) thread.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(errors[t], "") << "thread " << t;
    for (const auto& png : results) EXPECT_EQ(png, reference);
}

// One GL context per backend however many threads draw: a context per server thread made resident
// memory grow with the thread count, and OSMesa contexts on several threads at once share one
// unlocked window buffer inside Mesa (the libOSMesa crash of issue 14).
TEST(DiagramConcurrency, ContextsDoNotMultiplyWithThreads) {
    const LensSystem lens = loadBundledLens("dgauss.50mm");
    std::vector<std::thread> threads;
    for (int t = 0; t < 12; ++t)
        threads.emplace_back([&, t] {
            DiagramOptions options;
            options.width = 320 + 8 * t;
            options.height = 200;
            options.backend = DiagramBackendKind::OSMesa;
            options.lens.focusDistance = Setting{1000.0 + 100.0 * t, "focus"};
            drawLensDiagramPng(lens, options);
        });
    for (auto& thread : threads) thread.join();
    EXPECT_LE(liveDiagramContexts(), 2);  // OSMesa, and EGL if another test used it
}

TEST(DiagramConcurrency, AutoBackendDraws) {
    DiagramOptions options;
    options.width = 400;
    options.height = 200;
    options.backend = DiagramBackendKind::Auto;
    const RgbaImage image = renderDiagram(loadBundledLens("dgauss.50mm"), options);
    EXPECT_EQ(image.width, 400);
    EXPECT_EQ(image.height, 200);
}

}  // namespace
}  // namespace lenslab::test
