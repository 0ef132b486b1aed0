#pragma once
// The diagram's GL contexts: at most one per backend in the whole process, lent to one thread at
// a time. Not one per thread, for two reasons found under load:
// - OSMesa keeps a process-wide, unlocked list of window buffers and gives every context of the
//   same format and size the same buffer, so contexts current on several threads race on it
//   (segfaults inside libOSMesa with three HTTP threads drawing at once).
// - Each llvmpipe context keeps its own multisample framebuffers, compiled shaders and scene
//   bins; one per HTTP thread made resident memory grow with the number of threads.
// llvmpipe rasterises on its own worker threads, so drawing one diagram at a time loses little.
#include <memory>
#include <mutex>

#include "GlCanvas.h"
#include "LensDiagram.h"

namespace lenslab {

class DiagramBackend;

class CanvasLease {
public:
    // Waits for `kind`'s context (Auto: EGL, else OSMesa) and makes it current on this thread.
    // Throws DiagramError when the backend cannot start.
    explicit CanvasLease(DiagramBackendKind kind);
    ~CanvasLease();  // releases the context from this thread for the next borrower
    CanvasLease(const CanvasLease&) = delete;
    CanvasLease& operator=(const CanvasLease&) = delete;

    GlCanvas& canvas() { return *canvas_; }

private:
    std::unique_lock<std::mutex> lock_;
    DiagramBackend* backend_ = nullptr;
    GlCanvas* canvas_ = nullptr;
};

// How many diagram GL contexts exist now (for tests: it must not grow with the thread count).
int liveDiagramContexts();

}  // namespace lenslab
