#include "DiagramTestSupport.h"

#include <cmath>
#include <cstdlib>

#include "settings/LensAnalysis.h"

namespace lenslab::test {

std::vector<std::string> bundledLenses() {
    return {"dgauss.50mm", "dgauss", "wide.22mm", "wide", "telephoto.250mm", "telephoto", "fisheye.10mm", "fisheye"};
}

LensSystem loadBundledLens(const std::string& stem) {
    return loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + stem + ".dat");
}

RgbaImage renderDiagram(const LensSystem& lens, const DiagramOptions& options) {
    return decodePng(drawLensDiagramPng(lens, options));
}

DiagramPicture layoutDiagram(const LensSystem& lens, const DiagramOptions& options) {
    return composeDiagram(analyzeLens(lens, options.lens), lens.name, options);
}

Rgba pixelAt(const RgbaImage& image, Point2 p) {
    const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return {0, 0, 0, 0};
    const std::uint8_t* q = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
    return {q[0], q[1], q[2], q[3]};
}

bool near(Rgba a, Rgba b, int tolerance) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance;
}

bool showsColour(Rgba pixel, Rgba colour, double minCoverage) {
    // Coverage from the channel where the colour differs most from white, then all channels checked.
    const int channels[3][2] = {{pixel.r, colour.r}, {pixel.g, colour.g}, {pixel.b, colour.b}};
    int strongest = 0;
    for (int c = 1; c < 3; ++c)
        if (255 - channels[c][1] > 255 - channels[strongest][1]) strongest = c;
    const double t = (255.0 - channels[strongest][0]) / (255.0 - channels[strongest][1]);
    if (t < minCoverage || t > 1.1) return false;
    for (const auto& ch : channels)
        if (std::abs(ch[0] - (255.0 + t * (ch[1] - 255.0))) > 20) return false;
    return true;
}

bool showsNear(const RgbaImage& image, Point2 p, Rgba colour, double coverage) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (showsColour(pixelAt(image, {p.x + dx, p.y + dy}), colour, coverage)) return true;
    return false;
}

std::vector<int> rowsWithColour(const RgbaImage& image, int x, Rgba colour) {
    std::vector<int> rows;
    for (int y = 0; y < image.height; ++y)
        if (showsColour(pixelAt(image, {static_cast<double>(x), static_cast<double>(y)}), colour)) rows.push_back(y);
    return rows;
}

bool rayYAtX(const DiagramPicture& picture, const FanRay& ray, double x, double& y) {
    for (std::size_t i = 1; i < ray.points.size(); ++i) {
        const Point2 a = picture.view.toPicture(ray.points[i - 1]), b = picture.view.toPicture(ray.points[i]);
        if ((a.x - x) * (b.x - x) > 0 || a.x == b.x) continue;
        y = a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
        return true;
    }
    return false;
}

}  // namespace lenslab::test
