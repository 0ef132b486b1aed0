#pragma once
// The lens as geometry: surfaces at signed z positions (origin at the front vertex, +z toward the
// scene, film at negative z), with the media between them and their clear apertures.
#include <optional>
#include <string>
#include <vector>

#include "LensTable.h"

namespace lenslab {

struct Surface {
    double z = 0;               // vertex position, mm (<= 0)
    double radius = 0;          // mm, 0 = flat; positive: centre of curvature at z - radius
    double curvature = 0;       // 1 / radius, 0 for flat
    double indexAfter = 1;      // refractive index on the film side (air = 1)
    double apertureRadius = 0;  // clear semi-diameter, mm
    bool isStop = false;
    int line = 0;               // source line in the lens table
};

struct LensSystem {
    std::string name;
    std::vector<std::string> comments;
    std::vector<Surface> surfaces;  // front (scene side) to rear (film side)
    int stopIndex = -1;
    TableLayout layout = TableLayout::GapBefore;

    const Surface& stop() const { return surfaces[stopIndex]; }
    double frontZ() const { return surfaces.front().z; }
    double rearZ() const { return surfaces.back().z; }
    // Index of the medium on the scene side of surface i.
    double indexBefore(int i) const { return i == 0 ? 1.0 : surfaces[i - 1].indexAfter; }
};

// Surface sag at height h (how far the surface lies toward the film from its vertex plane).
double sag(const Surface& s, double h);

// Builds and validates the geometry. Throws LensTableError naming the table's line for: no stop or
// more than one, a diameter larger than the sphere allows, overlapping surfaces.
LensSystem buildLensSystem(const LensTable& table);

// readLensTable + buildLensSystem.
LensSystem loadLensSystem(const std::string& path, std::optional<TableLayout> layout = std::nullopt);

// The same lens with the aperture stop opened or closed to `diameter` (mm).
LensSystem withStopDiameter(const LensSystem& lens, double diameter);

}  // namespace lenslab
