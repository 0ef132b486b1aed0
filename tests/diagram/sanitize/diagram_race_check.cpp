// The diagram drawing path as the server runs it: several threads drawing diagrams nobody asked
// for before (cache misses: varied f-stop, focus, mode and size) on the OSMesa backend at once.
// Built with ThreadSanitizer and with AddressSanitizer (LENSLAB_SANITIZE_DIAGRAM); every picture
// must also equal the same diagram drawn alone. Exit status 0 when all do.
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "CanvasLease.h"
#include "LensDiagram.h"
#include "prescription/LensSystem.h"

#ifndef LENSLAB_SOURCE_DIR
#error "LENSLAB_SOURCE_DIR must be defined by the build"
#endif

namespace {

using namespace lenslab;

constexpr int kThreads = 4, kEach = 3;

DiagramOptions missOptions(int thread, int i) {
    static const DiagramMode modes[] = {DiagramMode::Exact, DiagramMode::Thick, DiagramMode::Overlay};
    DiagramOptions options;
    options.backend = DiagramBackendKind::OSMesa;
    options.width = 320 + 16 * thread;
    options.height = 200 + 8 * i;
    options.mode = modes[(thread + i) % 3];
    options.lens.fstop = Setting{2.8 + thread + 0.5 * i, "fstop"};
    options.lens.focusDistance = Setting{1000.0 + 250.0 * (thread * kEach + i), "focus"};
    return options;
}

}  // namespace

int main() {
    const LensSystem lens = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    std::vector<std::vector<std::uint8_t>> drawn(kThreads * kEach);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            for (int i = 0; i < kEach; ++i) drawn[t * kEach + i] = drawLensDiagramPng(lens, missOptions(t, i));
        });
    for (auto& thread : threads) thread.join();
    int wrong = 0;
    for (int t = 0; t < kThreads; ++t)
        for (int i = 0; i < kEach; ++i)
            if (drawLensDiagramPng(lens, missOptions(t, i)) != drawn[t * kEach + i]) {
                std::fprintf(stderr, "diagram %d of thread %d differs from the same diagram drawn alone\n", i, t);
                ++wrong;
            }
    std::printf("%d concurrent diagrams, %d wrong, %d GL context(s)\n", kThreads * kEach, wrong, liveDiagramContexts());
    return wrong == 0 && liveDiagramContexts() == 1 ? 0 : 1;
}
