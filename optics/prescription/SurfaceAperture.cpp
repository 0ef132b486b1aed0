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

std::optional<std::pair<double, double>> SurfaceAperture::meridionalSpan() const {
    // Half the chord the line x = 0 cuts, about centreY.
    const double u = std::fabs(centreX);
    double half = -1;
    switch (kind) {
        case ApertureKind::Rectangular: half = u <= halfWidthX ? halfWidthY : -1; break;
        case ApertureKind::Elliptical: half = u <= halfWidthX ? halfWidthY * std::sqrt(1 - (u / halfWidthX) * (u / halfWidthX)) : -1; break;
        case ApertureKind::Circular: half = u <= halfWidthX ? std::sqrt(halfWidthX * halfWidthX - u * u) : -1; break;
    }
    if (half < 0) return std::nullopt;
    return std::pair{centreY - half, centreY + half};
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
