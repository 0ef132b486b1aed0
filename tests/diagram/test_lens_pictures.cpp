// Every bundled lens drawn with both backends and read back: size, glass where the outline says,
// background around it, the axis, rays that converge toward the focus, and equal backends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "DiagramStyle.h"
#include "DiagramTestSupport.h"
#include "settings/LensAnalysis.h"

namespace lenslab::test {
namespace {

using namespace diagram_style;

class DiagramOfBundledLens : public ::testing::TestWithParam<std::string> {};

// Points halfway between the two faces of every element, over most of its height, that are at
// least a few pixels from either face.
std::vector<Point2> insideGlass(const DiagramPicture& picture, const LensSystem& lens) {
    std::vector<Point2> points;
    for (const GlassElement& g : buildLensOutline(lens).glass) {
        for (double f : {0.1, 0.2, 0.35, 0.65, 0.8, 0.9}) {
            const std::size_t i = static_cast<std::size_t>(f * (g.front.size() - 1));
            const Point2 a = picture.view.toPicture(g.front[i]), b = picture.view.toPicture(g.rear[i]);
            if (b.x - a.x >= 8) points.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
        }
    }
    return points;
}

double maxChannelDifferenceFraction(const RgbaImage& a, const RgbaImage& b, int tolerance) {
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            if (std::abs(a.rgba[i + c] - b.rgba[i + c]) > tolerance) {
                ++differing;
                break;
            }
    return static_cast<double>(differing) / (a.rgba.size() / 4);
}

// Vertical extent (pixels) of exact-ray colour in column x, inside the content box.
int rayExtent(const RgbaImage& image, const DiagramPicture& picture, int x) {
    std::vector<int> rows = rowsWithColour(image, x, kExactRay);
    rows.erase(std::remove_if(rows.begin(), rows.end(),
                              [&](int y) { return y < picture.content.top || y > picture.content.bottom; }),
               rows.end());
    return rows.empty() ? 0 : rows.back() - rows.front();
}

TEST_P(DiagramOfBundledLens, DrawsLensAxisAndRaysOnBothBackends) {
    const LensSystem lens = loadBundledLens(GetParam());
    DiagramOptions options;
    const LensAnalysis analysis = analyzeLens(lens, options.lens);
    const DiagramPicture picture = layoutDiagram(lens, options);

    options.backend = DiagramBackendKind::OSMesa;
    const RgbaImage osmesa = renderDiagram(lens, options);
    options.backend = DiagramBackendKind::EGL;
    const RgbaImage egl = renderDiagram(lens, options);

    for (const RgbaImage* image : {&osmesa, &egl}) {
        ASSERT_EQ(image->width, 1200);
        ASSERT_EQ(image->height, 600);

        const std::vector<Point2> glass = insideGlass(picture, analysis.lens);
        ASSERT_GE(glass.size(), 4u);
        const auto tinted = std::count_if(glass.begin(), glass.end(),
                                          [&](Point2 p) { return near(pixelAt(*image, p), kGlass, 12); });
        EXPECT_GE(tinted, static_cast<long>(glass.size() * 6 / 10)) << "glass samples: " << glass.size();

        const double xFilm = picture.view.toPicture({analysis.focus.imageZExact, 0}).x;
        const double axisY = picture.view.yAtAxis;
        const Point2 behindFilm{(xFilm + picture.content.right) / 2 + 2, axisY - 0.4 * (axisY - picture.content.top)};
        EXPECT_TRUE(near(pixelAt(*image, behindFilm), kBackground, 0));
        EXPECT_TRUE(near(pixelAt(*image, {2, 2}), kBackground, 0));

        int axisPixels = 0, axisRun = 0;
        for (int x = static_cast<int>(xFilm) + 6; x < picture.content.right; ++x, ++axisRun)
            axisPixels += near(pixelAt(*image, {static_cast<double>(x), axisY}), kAxis, 30);
        EXPECT_GE(axisPixels, axisRun * 4 / 10) << "dashed axis behind the film";

        long rayPixels = 0;
        for (std::size_t i = 0; i < image->rgba.size(); i += 4)
            rayPixels += showsColour({image->rgba[i], image->rgba[i + 1], image->rgba[i + 2]}, kExactRay);
        EXPECT_GT(rayPixels, 2000);
    }
    EXPECT_LT(maxChannelDifferenceFraction(osmesa, egl, 8), 0.001);
}

// The axial fan, focused on a near object, narrows from the front of the lens to the object.
TEST_P(DiagramOfBundledLens, AxialFanConvergesOnTheFocusedObject) {
    const LensSystem lens = loadBundledLens(GetParam());
    DiagramOptions options;
    options.fieldHeight = 0.0;
    const LensAnalysis infinity = analyzeLens(lens, options.lens);
    // Near enough to be in the picture, far enough for the lens to focus (the telephoto's F is far out).
    const double focus = std::max(1.2 * (lens.frontZ() - infinity.focus.imageZExact), 1.1 * closestFocusDistance(infinity.firstOrder));
    options.lens.focusDistance = Setting{focus, "focus"};
    const DiagramPicture picture = layoutDiagram(lens, options);
    const RgbaImage image = renderDiagram(lens, options);

    const double objectZ = lens.frontZ() + focus;
    const double xFront = picture.view.toPicture({lens.frontZ(), 0}).x;
    const double xObject = picture.view.toPicture({objectZ, 0}).x;
    ASSERT_GT(xObject, picture.content.left);
    const int wide = rayExtent(image, picture, static_cast<int>(xFront - 4));
    const int narrow = rayExtent(image, picture, static_cast<int>(xObject + 0.15 * (xFront - xObject)));
    EXPECT_GT(wide, 10);  // the fisheye's entrance pupil is 2.5 mm: about 18 px here
    EXPECT_LT(narrow, 0.35 * wide) << "wide " << wide << " narrow " << narrow;
}

INSTANTIATE_TEST_SUITE_P(Lenses, DiagramOfBundledLens, ::testing::ValuesIn(bundledLenses()), [](const auto& info) {
    std::string name = info.param;
    std::replace(name.begin(), name.end(), '.', '_');
    return name;
});

}  // namespace
}  // namespace lenslab::test
