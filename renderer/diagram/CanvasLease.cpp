#include "CanvasLease.h"

#include <atomic>
#include <string>

#include "DiagramBackend.h"

namespace lenslab {

namespace {

std::atomic<int> liveContexts{0};

// One backend's context and canvas, made on first use and kept for the life of the process (a
// fresh llvmpipe context recompiles its shaders, which costs several times a drawing). A backend
// that failed to start is remembered so that every request does not pay for trying again.
struct SharedContext {
    std::mutex mutex;
    std::unique_ptr<DiagramBackend> backend;
    std::unique_ptr<GlCanvas> canvas;
    std::string failure;

    // Needs `mutex` held; leaves the context current on this thread.
    void start(DiagramBackendKind kind) {
        if (!failure.empty()) throw DiagramError(failure);
        if (backend) {
            backend->makeCurrent();
            return;
        }
        try {
            auto made = createDiagramBackend(kind);
            canvas = std::make_unique<GlCanvas>();
            backend = std::move(made);
            ++liveContexts;
        } catch (const DiagramError& error) {
            failure = error.what();
            throw;
        }
    }
};

SharedContext& sharedContext(DiagramBackendKind kind) {
    // Never destroyed: worker threads may still draw while static destructors run at exit.
    static auto* const osmesa = new SharedContext;
    static auto* const egl = new SharedContext;
    return kind == DiagramBackendKind::OSMesa ? *osmesa : *egl;
}

}  // namespace

CanvasLease::CanvasLease(DiagramBackendKind kind) {
    auto borrow = [this](DiagramBackendKind concrete) {
        SharedContext& shared = sharedContext(concrete);
        std::unique_lock<std::mutex> lock(shared.mutex);
        shared.start(concrete);
        lock_ = std::move(lock);
        backend_ = shared.backend.get();
        canvas_ = shared.canvas.get();
    };
    if (kind != DiagramBackendKind::Auto) {
        borrow(kind);
        return;
    }
    try {
        borrow(DiagramBackendKind::EGL);
    } catch (const DiagramError&) {
        borrow(DiagramBackendKind::OSMesa);
    }
}

CanvasLease::~CanvasLease() { backend_->releaseCurrent(); }

int liveDiagramContexts() { return liveContexts.load(); }

}  // namespace lenslab
