#include "ThreadContexts.h"

#include <memory>

#include "DiagramBackend.h"

namespace lenslab {

namespace {

struct WarmContext {
    std::unique_ptr<DiagramBackend> backend;
    std::unique_ptr<GlCanvas> canvas;

    ~WarmContext() {
        if (!backend) return;
        try {
            backend->makeCurrent();  // the canvas's GL objects belong to this context
            canvas.reset();
        } catch (const DiagramError&) {
            canvas.release();  // the context is going anyway; its objects go with it
        }
    }
};

GlCanvas& warm(WarmContext& slot, DiagramBackendKind kind) {
    if (!slot.backend) {
        auto backend = createDiagramBackend(kind);
        slot.canvas = std::make_unique<GlCanvas>();
        slot.backend = std::move(backend);
    } else {
        slot.backend->makeCurrent();
    }
    return *slot.canvas;
}

}  // namespace

GlCanvas& threadCanvas(DiagramBackendKind kind) {
    thread_local WarmContext osmesa, egl;
    if (kind == DiagramBackendKind::OSMesa) return warm(osmesa, kind);
    if (kind == DiagramBackendKind::EGL) return warm(egl, kind);
    try {
        return warm(egl, DiagramBackendKind::EGL);
    } catch (const DiagramError&) {
        return warm(osmesa, DiagramBackendKind::OSMesa);
    }
}

}  // namespace lenslab
