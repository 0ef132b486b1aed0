// The thick-lens approximation against the real lens, measured on the picture (pixels): both models
// trace the same incoming rays, which arrive together near the axis and, for the fisheye, part far
// at its off-axis field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "DiagramStyle.h"
#include "DiagramTestSupport.h"
#include "RayFans.h"

namespace lenslab::test {
namespace {

struct FanPair {
    std::vector<const FanRay*> exact, thick;  // same order: ray k of one matches ray k of the other
};

FanPair fan(const DiagramPicture& picture, bool offAxis) {
    FanPair f;
    for (const FanRay& ray : picture.rays)
        if (ray.offAxis == offAxis) (ray.model == RayModel::Exact ? f.exact : f.thick).push_back(&ray);
    return f;
}

// Largest on-picture separation at column x between matching rays both models let through.
double largestSeparation(const DiagramPicture& picture, const FanPair& f, double x, std::size_t* which = nullptr) {
    double largest = 0;
    for (std::size_t k = 0; k < f.exact.size(); ++k) {
        double ye = 0, yt = 0;
        if (f.exact[k]->blocked || f.thick[k]->blocked) continue;
        if (!rayYAtX(picture, *f.exact[k], x, ye) || !rayYAtX(picture, *f.thick[k], x, yt)) continue;
        if (std::abs(ye - yt) > largest) {
            largest = std::abs(ye - yt);
            if (which) *which = k;
        }
    }
    return largest;
}

// Where the rays arrive: the picture column just in front of the film, where every ray that passes ends.
double columnBeforeFilm(const DiagramPicture& picture) {
    const auto arriving = std::find_if(picture.rays.begin(), picture.rays.end(), [](const FanRay& r) { return !r.blocked; });
    EXPECT_NE(arriving, picture.rays.end());
    return picture.view.toPicture({arriving->points.back().z, 0}).x - 2;
}

bool colourNear(const RgbaImage& image, int x, double y, Rgba colour) {
    const std::vector<int> rows = rowsWithColour(image, x, colour);
    return std::any_of(rows.begin(), rows.end(), [&](int r) { return std::abs(r + 0.5 - y) <= 3; });
}

// Traced forward from the same incoming rays, the two models bring the near-axis rays of the axial
// fan to the same film point (the thick lens is the paraxial lens), for a rectilinear wide angle and
// a fisheye alike.
class ThickVsExact : public ::testing::TestWithParam<std::string> {};

TEST_P(ThickVsExact, NearAxisRaysArriveTogether) {
    DiagramOptions options;
    options.mode = DiagramMode::Overlay;
    const DiagramPicture picture = layoutDiagram(loadBundledLens(GetParam()), options);
    // The axial fan without its outer rays (within 30% of the stop's radius).
    FanPair axial = fan(picture, false);
    const std::size_t middle = axial.exact.size() / 2;
    axial.exact = {axial.exact.begin() + middle - 1, axial.exact.begin() + middle + 2};
    axial.thick = {axial.thick.begin() + middle - 1, axial.thick.begin() + middle + 2};
    const double nearAxis = largestSeparation(picture, axial, columnBeforeFilm(picture));
    RecordProperty("near_axis_px", std::to_string(nearAxis));
    EXPECT_LT(nearAxis, 1.5) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(WideAndFisheye, ThickVsExact, ::testing::Values("wide.22mm", "fisheye.10mm"),
                         [](const auto& info) { return info.param == "wide.22mm" ? "wide_22mm" : "fisheye_10mm"; });

// The fisheye's real projection (about f theta) is far from the thick lens's (f tan theta): at its
// off-axis field the two fans land far apart on the film, by far more than a rectilinear wide angle's,
// whose distortion is small.
TEST(ThickVsExact, FisheyeFieldLandsFarFromItsThickLensImage) {
    auto rimSeparation = [](const std::string& stem) {
        DiagramOptions options;
        options.mode = DiagramMode::Overlay;
        const DiagramPicture picture = layoutDiagram(loadBundledLens(stem), options);
        return largestSeparation(picture, fan(picture, true), columnBeforeFilm(picture));
    };
    const double fisheye = rimSeparation("fisheye.10mm"), wide = rimSeparation("wide.22mm");
    RecordProperty("fisheye_field_px", std::to_string(fisheye));
    RecordProperty("wide_field_px", std::to_string(wide));
    EXPECT_GT(fisheye, 30.0);
    EXPECT_GT(fisheye, 5 * wide);
}

// On the rendered overlay, each model's ray of the fisheye's off-axis fan is where the layout says,
// in its own colour, at the first column behind the lens where the two are 4 px apart.
TEST(ThickVsExact, PartedRaysShowInTheirOwnColours) {
    const LensSystem lens = loadBundledLens("fisheye.10mm");
    DiagramOptions options;
    options.mode = DiagramMode::Overlay;
    const DiagramPicture picture = layoutDiagram(lens, options);
    const double filmColumn = columnBeforeFilm(picture);
    std::size_t rimRay = 0;
    const FanPair field = fan(picture, true);
    largestSeparation(picture, field, filmColumn, &rimRay);
    const RgbaImage image = renderDiagram(lens, options);
    const double xRear = picture.view.toPicture({lens.rearZ(), 0}).x;
    for (int x = static_cast<int>(xRear) + 3; x < filmColumn; ++x) {
        double ye = 0, yt = 0;
        rayYAtX(picture, *field.exact[rimRay], x, ye);
        rayYAtX(picture, *field.thick[rimRay], x, yt);
        const auto inside = [&](double y) { return y > picture.content.top + 3 && y < picture.content.bottom - 3; };
        if (std::abs(ye - yt) < 4 || !inside(ye) || !inside(yt)) continue;
        EXPECT_TRUE(colourNear(image, x, ye, diagram_style::kExactRay)) << "column " << x << " row " << ye;
        EXPECT_TRUE(colourNear(image, x, yt, diagram_style::kThickRay)) << "column " << x << " row " << yt;
        return;
    }
    ADD_FAILURE() << "the rays never part inside the picture";
}

}  // namespace
}  // namespace lenslab::test

namespace lenslab::test {
namespace {

// The thick lens's rays run from the object to the front principal plane P and leave the rear one P'
// at the same height (the planes of unit magnification), then converge on the film where the thick
// lens focuses: drawn to P' on both sides, or with the heights changed, the fan would be another lens's.
TEST(ThickLensFan, ReachesPPrimeAndLeavesPAtTheSameHeight) {
    for (const char* name : {"dgauss.50mm", "telephoto.250mm", "wide.22mm"}) {
        const LensSystem lens = loadBundledLens(name);
        const double focus = 3000;
        const LensAnalysis a = analyzeLens(lens, std::nullopt, focus);
        FanSetup setup;
        setup.filmZ = a.focus.imageZThick;
        setup.rays = 7;
        setup.startZ = lens.frontZ() + 2 * focus;
        int checked = 0;
        for (const FanRay& r : traceRayFans(a, RayModel::Thick, setup)) {
            if (r.blocked) continue;
            ASSERT_EQ(r.points.size(), 4u) << name;
            EXPECT_NEAR(r.points[0].z, lens.frontZ() + focus, 1e-9) << name;  // the axial object point
            EXPECT_NEAR(r.points[0].y, 0, 1e-9) << name;
            EXPECT_NEAR(r.points[1].z, a.thick.zP, 1e-9) << name;
            EXPECT_NEAR(r.points[2].z, a.thick.zPPrime, 1e-9) << name;
            EXPECT_NEAR(r.points[2].y, r.points[1].y, 1e-9) << name;
            // Beyond P' the ray ends on the film at the object's thick-lens image, on the axis.
            EXPECT_NEAR(r.points[3].z, setup.filmZ, 1e-9) << name;
            EXPECT_NEAR(r.points[3].y, 0, 1e-9 * focus) << name;
            ++checked;
        }
        EXPECT_GE(checked, 5) << name;
    }
}

}  // namespace
}  // namespace lenslab::test
