#pragma once
// An offscreen OpenGL 3.3 core context, current on the thread that created it, with that thread's
// GL function table loaded from it. Destroying it releases the context.
#include <memory>
#include <string>

#include "LensDiagram.h"

namespace lenslab {

class DiagramBackend {
public:
    virtual ~DiagramBackend() = default;
    virtual const char* name() const = 0;
    // Makes the context current on the calling thread and loads that thread's GL table from it.
    virtual void makeCurrent() = 0;
    // Leaves the calling thread with no current context, so another thread may take this one.
    virtual void releaseCurrent() = 0;
};

// Each throws DiagramError with the reason when its platform cannot give a context.
std::unique_ptr<DiagramBackend> createOSMesaBackend();
std::unique_ptr<DiagramBackend> createEglBackend();

// OSMesa or EGL as asked; Auto tries EGL (a GPU when there is one) and falls back to OSMesa.
std::unique_ptr<DiagramBackend> createDiagramBackend(DiagramBackendKind kind);

}  // namespace lenslab
