#include "ViewFit.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

ViewTransform fitView(double zMin, double zMax, double yMin, double yMax, const PictureBox& box) {
    const double width = box.right - box.left, height = box.bottom - box.top;
    ViewTransform v;
    v.scale = std::min(width / (zMax - zMin), height / (yMax - yMin));
    v.xAtZ0 = 0.5 * (box.left + box.right) + 0.5 * (zMin + zMax) * v.scale;
    // On a pixel centre, so the one-pixel axis stays crisp.
    v.yAtAxis = std::floor(0.5 * (box.top + box.bottom) + 0.5 * (yMin + yMax) * v.scale) + 0.5;
    return v;
}

ViewTransform fitView(double zMin, double zMax, double yHalf, const PictureBox& box) {
    return fitView(zMin, zMax, -yHalf, yHalf, box);
}

ZYBounds ZYBounds::around(const std::vector<ZY>& points) {
    ZYBounds b{points.front().z, points.front().z, points.front().y, points.front().y};
    for (const ZY& p : points) {
        b.zMin = std::min(b.zMin, p.z);
        b.zMax = std::max(b.zMax, p.z);
        b.yMin = std::min(b.yMin, p.y);
        b.yMax = std::max(b.yMax, p.y);
    }
    return b;
}

namespace {

// Clips segment a-b to the box; false when nothing is inside.
bool clipSegment(Point2& a, Point2& b, const PictureBox& box) {
    double t0 = 0, t1 = 1;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - box.left, box.right - a.x, a.y - box.top, box.bottom - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
    const Point2 start{a.x + t0 * dx, a.y + t0 * dy};
    b = {a.x + t1 * dx, a.y + t1 * dy};
    a = start;
    return true;
}

}  // namespace

std::vector<std::vector<Point2>> clipPolyline(const std::vector<Point2>& points, const PictureBox& box) {
    std::vector<std::vector<Point2>> pieces;
    bool open = false;  // the last piece continues at the current point
    for (std::size_t i = 1; i < points.size(); ++i) {
        Point2 a = points[i - 1], b = points[i];
        const bool whole = clipSegment(a, b, box);
        if (!whole) {
            open = false;
            continue;
        }
        if (!open) pieces.push_back({a});
        pieces.back().push_back(b);
        // The piece stays open only when the segment's end was not cut.
        open = b.x == points[i].x && b.y == points[i].y;
    }
    return pieces;
}

}  // namespace lenslab
