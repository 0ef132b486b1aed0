#include "DrawList.h"

#include <algorithm>
#include <cmath>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

Vertex vertex(Point2 p, Rgba colour) { return {static_cast<float>(p.x), static_cast<float>(p.y), colour}; }

}  // namespace

void addTriangle(DrawList& list, Point2 a, Point2 b, Point2 c, Rgba colour) {
    list.vertices.push_back(vertex(a, colour));
    list.vertices.push_back(vertex(b, colour));
    list.vertices.push_back(vertex(c, colour));
}

void addQuad(DrawList& list, Point2 a, Point2 b, Point2 c, Point2 d, Rgba colour) {
    addTriangle(list, a, b, c, colour);
    addTriangle(list, a, c, d, colour);
}

void addRectangle(DrawList& list, Point2 topLeft, Point2 bottomRight, Rgba colour) {
    addQuad(list, topLeft, {bottomRight.x, topLeft.y}, bottomRight, {topLeft.x, bottomRight.y}, colour);
}

void addLine(DrawList& list, Point2 a, Point2 b, double width, Rgba colour) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length = std::hypot(dx, dy);
    if (!(length > 0)) return;
    const double h = 0.5 * width;
    const double ux = dx / length * h, uy = dy / length * h;  // along, half a width
    const double nx = -uy, ny = ux;                           // across, half a width
    addQuad(list, {a.x - ux + nx, a.y - uy + ny}, {b.x + ux + nx, b.y + uy + ny}, {b.x + ux - nx, b.y + uy - ny},
            {a.x - ux - nx, a.y - uy - ny}, colour);
}

void addPolyline(DrawList& list, const std::vector<Point2>& points, double width, Rgba colour) {
    for (std::size_t i = 1; i < points.size(); ++i) addLine(list, points[i - 1], points[i], width, colour);
}

void addDashedPolyline(DrawList& list, const std::vector<Point2>& points, double width, double dash,
                       double gap, Rgba colour) {
    const double period = dash + gap;
    double phase = 0;  // distance along the pattern at the start of the current segment
    for (std::size_t i = 1; i < points.size(); ++i) {
        const Point2 a = points[i - 1], b = points[i];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        if (!(length > 0)) continue;
        auto at = [&](double s) { return Point2{a.x + (b.x - a.x) * s / length, a.y + (b.y - a.y) * s / length}; };
        for (double s = -std::fmod(phase, period); s < length; s += period) {
            const double from = std::max(s, 0.0), to = std::min(s + dash, length);
            if (to > from) addLine(list, at(from), at(to), width, colour);
        }
        phase += length;
    }
}

void addDisc(DrawList& list, Point2 centre, double radius, Rgba colour) {
    const int steps = std::clamp(static_cast<int>(radius * 3), 12, 48);
    for (int i = 0; i < steps; ++i) {
        const double a0 = 2 * kPi * i / steps, a1 = 2 * kPi * (i + 1) / steps;
        addTriangle(list, centre, {centre.x + radius * std::cos(a0), centre.y + radius * std::sin(a0)},
                    {centre.x + radius * std::cos(a1), centre.y + radius * std::sin(a1)}, colour);
    }
}

void addCross(DrawList& list, Point2 c, double halfSize, double width, Rgba colour) {
    addLine(list, {c.x - halfSize, c.y - halfSize}, {c.x + halfSize, c.y + halfSize}, width, colour);
    addLine(list, {c.x - halfSize, c.y + halfSize}, {c.x + halfSize, c.y - halfSize}, width, colour);
}

void addArrowHead(DrawList& list, Point2 tip, double dx, double dy, double size, Rgba colour) {
    const double length = std::hypot(dx, dy);
    if (!(length > 0)) return;
    const double ux = dx / length, uy = dy / length;
    const Point2 base{tip.x - ux * size, tip.y - uy * size};
    addTriangle(list, tip, {base.x - uy * size * 0.45, base.y + ux * size * 0.45},
                {base.x + uy * size * 0.45, base.y - ux * size * 0.45}, colour);
}

}  // namespace lenslab
