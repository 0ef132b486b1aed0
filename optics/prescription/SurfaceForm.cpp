#include "prescription/SurfaceForm.h"

namespace lenslab {

const char* surfaceKindName(SurfaceKind kind) {
    switch (kind) {
        case SurfaceKind::EvenAsphere: return "even asphere";
        case SurfaceKind::OddAsphere: return "odd asphere";
        case SurfaceKind::Qbfs: return "Qbfs";
        case SurfaceKind::Qcon: return "Qcon";
        case SurfaceKind::Toroidal: return "toroidal";
    }
    return "unknown";
}

}  // namespace lenslab
