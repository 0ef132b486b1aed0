#pragma once
// Shapes in picture coordinates (pixels, origin top-left, y down) as coloured triangles, ready
// for one OpenGL draw call. Lines are quads of a given width so they look the same on every
// backend (core profiles have no wide lines); multisampling anti-aliases the edges.
#include <cstdint>
#include <vector>

namespace lenslab {

struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

struct Point2 {
    double x = 0, y = 0;
};

struct Vertex {
    float x, y;
    Rgba colour;
};

struct DrawList {
    std::vector<Vertex> vertices;  // three per triangle
};

void addTriangle(DrawList& list, Point2 a, Point2 b, Point2 c, Rgba colour);
// The quad a-b-c-d (in order around it).
void addQuad(DrawList& list, Point2 a, Point2 b, Point2 c, Point2 d, Rgba colour);
void addRectangle(DrawList& list, Point2 topLeft, Point2 bottomRight, Rgba colour);
// Segments with square caps half a width long, which also fill the joints of a polyline.
void addLine(DrawList& list, Point2 a, Point2 b, double width, Rgba colour);
void addPolyline(DrawList& list, const std::vector<Point2>& points, double width, Rgba colour);
void addDashedPolyline(DrawList& list, const std::vector<Point2>& points, double width, double dash,
                       double gap, Rgba colour);
void addDisc(DrawList& list, Point2 centre, double radius, Rgba colour);
void addCross(DrawList& list, Point2 centre, double halfSize, double width, Rgba colour);
// A filled arrow head with its tip at `tip`, pointing along (dx, dy).
void addArrowHead(DrawList& list, Point2 tip, double dx, double dy, double size, Rgba colour);

}  // namespace lenslab
