#pragma once
// Helpers shared by the diagram tests: bundled lenses, pixel access and ray positions on the picture.
#include <string>
#include <vector>

#include "DiagramPicture.h"
#include "DrawList.h"
#include "LensDiagram.h"
#include "PngCodec.h"

namespace lenslab::test {

// The eight lens tables under lenses/ (stems, e.g. "dgauss.50mm").
std::vector<std::string> bundledLenses();
LensSystem loadBundledLens(const std::string& stem);

RgbaImage renderDiagram(const LensSystem& lens, const DiagramOptions& options);
// The picture layout drawLensDiagramPng uses for the same options.
DiagramPicture layoutDiagram(const LensSystem& lens, const DiagramOptions& options);

Rgba pixelAt(const RgbaImage& image, Point2 p);
bool near(Rgba a, Rgba b, int tolerance);
// `colour` drawn over white with at least `minCoverage` (anti-aliased line edges included).
bool showsColour(Rgba pixel, Rgba colour, double minCoverage = 0.35);
// Whether `colour` shows within a pixel of p, at least at `coverage`.
bool showsNear(const RgbaImage& image, Point2 p, Rgba colour, double coverage = 0.5);
// Rows in column x that show `colour`.
std::vector<int> rowsWithColour(const RgbaImage& image, int x, Rgba colour);

// Picture y of a ray's drawn path at picture column x; false when the path does not cross x.
bool rayYAtX(const DiagramPicture& picture, const FanRay& ray, double x, double& y);

}  // namespace lenslab::test
