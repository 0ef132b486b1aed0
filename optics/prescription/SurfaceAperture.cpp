#include "prescription/SurfaceAperture.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

double SurfaceAperture::reach() const {
    const double cx = std::fabs(centreX), cy = std::fabs(centreY);
    switch (kind) {
        case ApertureKind::Rectangular: return std::hypot(cx + halfWidthX, cy + halfWidthY);
        case ApertureKind::Elliptical: return std::hypot(cx, cy) + std::max(halfWidthX, halfWidthY);
        case ApertureKind::Circular: break;
    }
    return std::hypot(cx, cy) + halfWidthX;
}

const char* apertureKindName(ApertureKind kind) {
    switch (kind) {
        case ApertureKind::Circular: return "circular";
        case ApertureKind::Rectangular: return "rectangular";
        case ApertureKind::Elliptical: return "elliptical";
    }
    return "unknown";
}

}  // namespace lenslab
