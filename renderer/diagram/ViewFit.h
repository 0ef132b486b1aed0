#pragma once
// Auto-fit of lens millimetres into a box of the picture. Front (scene side, +z) to the LEFT as in
// lens drawings: picture x grows as z falls; picture y grows downward as y falls.
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

// The largest scale that shows z in [zMin, zMax] and y in [-yHalf, yHalf] inside the box, centred.
ViewTransform fitView(double zMin, double zMax, double yHalf, const PictureBox& box);

// The pieces of a polyline inside the box (Liang-Barsky on each segment).
std::vector<std::vector<Point2>> clipPolyline(const std::vector<Point2>& points, const PictureBox& box);

}  // namespace lenslab
