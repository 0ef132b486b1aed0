#pragma once
// Auto-fit of lens millimetres into a box of the picture. Front (scene side, +z) to the LEFT as in
// lens drawings: picture x grows as z falls; picture y grows downward as y falls.
#include <algorithm>
#include <vector>

#include "DrawList.h"
#include "LensOutline.h"

namespace lenslab {

struct PictureBox {
    double left = 0, top = 0, right = 0, bottom = 0;  // pixels
};

struct ViewTransform {
    double scale = 1;              // pixels per mm
    double xAtZ0 = 0, yAtAxis = 0;  // picture position of z = 0 and of the axis
    Point2 toPicture(ZY p) const { return {xAtZ0 - p.z * scale, yAtAxis - p.y * scale}; }
    double zAt(double x) const { return (xAtZ0 - x) / scale; }
    double yAt(double y) const { return (yAtAxis - y) / scale; }
};

// The largest scale that shows z in [zMin, zMax] and y in [yMin, yMax] inside the box, centred, the
// axis (y = 0) on a pixel centre.
ViewTransform fitView(double zMin, double zMax, double yMin, double yMax, const PictureBox& box);
// The same for y in [-yHalf, yHalf]: the axis across the box's middle.
ViewTransform fitView(double zMin, double zMax, double yHalf, const PictureBox& box);

// The smallest box of z and y holding every point.
struct ZYBounds {
    double zMin = 0, zMax = 0, yMin = 0, yMax = 0;
    static ZYBounds around(const std::vector<ZY>& points);  // points not empty
    bool holds(ZY p) const { return p.z >= zMin && p.z <= zMax && p.y >= yMin && p.y <= yMax; }
    ZYBounds grownBy(double margin) const { return {zMin - margin, zMax + margin, yMin - margin, yMax + margin}; }
    double span() const { return std::max(zMax - zMin, yMax - yMin); }
};

// The pieces of a polyline inside the box (Liang-Barsky on each segment).
std::vector<std::vector<Point2>> clipPolyline(const std::vector<Point2>& points, const PictureBox& box);

}  // namespace lenslab
