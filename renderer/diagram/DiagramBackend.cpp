#include "DiagramBackend.h"

namespace lenslab {

std::unique_ptr<DiagramBackend> createDiagramBackend(DiagramBackendKind kind) {
    switch (kind) {
        case DiagramBackendKind::OSMesa: return createOSMesaBackend();
        case DiagramBackendKind::EGL: return createEglBackend();
        case DiagramBackendKind::Auto: break;
    }
    try {
        return createEglBackend();
    } catch (const DiagramError&) {
        return createOSMesaBackend();
    }
}

}  // namespace lenslab
