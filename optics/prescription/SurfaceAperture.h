#pragma once
// A clear aperture or an obscuration other than a circle about the vertex: a circle, rectangle or
// ellipse, decentred in the surface's own x and y (Zemax SQAP, ELAP, SQOB, ELOB with OBDC; Code V
// CIR, REX/REY, ELX/ELY with ADX/ADY).
#include <cstdint>
#include <optional>
#include <utility>

namespace lenslab {

enum class ApertureKind : std::uint8_t { Circular, Rectangular, Elliptical };

struct SurfaceAperture {
    ApertureKind kind = ApertureKind::Circular;
    double halfWidthX = 0, halfWidthY = 0;  // mm; a circle's radius is both
    double centreX = 0, centreY = 0;        // decentre in the surface's plane, mm

    // Whether the point (x, y) of the surface's plane lies inside (the edge included).
    bool contains(double x, double y) const {
        const double u = x - centreX, v = y - centreY;
        switch (kind) {
            case ApertureKind::Rectangular: return (u < 0 ? -u : u) <= halfWidthX && (v < 0 ? -v : v) <= halfWidthY;
            case ApertureKind::Elliptical:
                return (u * u) / (halfWidthX * halfWidthX) + (v * v) / (halfWidthY * halfWidthY) <= 1;
            case ApertureKind::Circular: break;
        }
        return u * u + v * v <= halfWidthX * halfWidthX;
    }
    // The radius about the vertex that holds the whole shape (the semi-diameter it needs).
    double reach() const;
    // The heights y where the line x = 0 runs inside the shape (the meridional section, as a lens
    // drawing shows it), low then high; nullopt when the line misses it.
    std::optional<std::pair<double, double>> meridionalSpan() const;
};

const char* apertureKindName(ApertureKind kind);  // "circular", "rectangular", "elliptical"

}  // namespace lenslab
