// The thick-lens approximation against the real lens, measured on the picture (pixels): the fans
// agree near the axis, and part at the rim of the off-axis fan for the wide-angle and fisheye lenses.
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

long passing(const std::vector<const FanRay*>& rays) {
    return std::count_if(rays.begin(), rays.end(), [](const FanRay* r) { return !r->blocked; });
}

bool colourNear(const RgbaImage& image, int x, double y, Rgba colour) {
    const std::vector<int> rows = rowsWithColour(image, x, colour);
    return std::any_of(rows.begin(), rows.end(), [&](int r) { return std::abs(r + 0.5 - y) <= 3; });
}

class ThickVsExact : public ::testing::TestWithParam<std::string> {};

TEST_P(ThickVsExact, FansAgreeNearAxisAndPartAtFieldRim) {
    const LensSystem lens = loadBundledLens(GetParam());
    DiagramOptions options;
    options.mode = DiagramMode::Overlay;
    const DiagramPicture picture = layoutDiagram(lens, options);
    const double farColumn = picture.content.left + 2;  // where the rays end, in front of the lens

    // Near the axis: the axial fan without its outer rays (within 40% of the pupil radius).
    FanPair axial = fan(picture, false);
    const std::size_t middle = axial.exact.size() / 2;
    axial.exact = {axial.exact.begin() + middle - 1, axial.exact.begin() + middle + 2};
    axial.thick = {axial.thick.begin() + middle - 1, axial.thick.begin() + middle + 2};
    const double nearAxis = largestSeparation(picture, axial, farColumn);

    std::size_t rimRay = 0;
    const FanPair field = fan(picture, true);
    const double rim = largestSeparation(picture, field, farColumn, &rimRay);
    RecordProperty("near_axis_px", std::to_string(nearAxis));
    RecordProperty("field_rim_px", std::to_string(rim));
    EXPECT_LT(nearAxis, 1.5) << GetParam();
    EXPECT_GT(rim, std::max(6.0, 5 * nearAxis)) << GetParam() << " near axis " << nearAxis;
    // The paraxial pupils also let through rim rays the real lens vignettes.
    EXPECT_GT(passing(field.thick), passing(field.exact));

    // On the rendered overlay, each model's rim ray is where the layout says, in its own colour,
    // at the first column in front of the lens where they are 4 px apart inside the picture.
    const RgbaImage image = renderDiagram(lens, options);
    const double xFront = picture.view.toPicture({lens.frontZ(), 0}).x;
    for (int x = static_cast<int>(xFront) - 3; x > farColumn; --x) {
        double ye = 0, yt = 0;
        rayYAtX(picture, *field.exact[rimRay], x, ye);
        rayYAtX(picture, *field.thick[rimRay], x, yt);
        const auto inside = [&](double y) { return y > picture.content.top + 3 && y < picture.content.bottom - 3; };
        if (std::abs(ye - yt) < 4 || !inside(ye) || !inside(yt)) continue;
        EXPECT_TRUE(colourNear(image, x, ye, diagram_style::kExactRay)) << "column " << x << " row " << ye;
        EXPECT_TRUE(colourNear(image, x, yt, diagram_style::kThickRay)) << "column " << x << " row " << yt;
        return;
    }
    ADD_FAILURE() << "the rim rays never part inside the picture";
}

INSTANTIATE_TEST_SUITE_P(WideAndFisheye, ThickVsExact, ::testing::Values("wide.22mm", "fisheye.10mm"),
                         [](const auto& info) { return info.param == "wide.22mm" ? "wide_22mm" : "fisheye_10mm"; });

// The fisheye's real projection is far from the thick lens's: its rim rays part by far more.
TEST(ThickVsExact, FisheyePartsFarMoreThanWideAngle) {
    auto rimSeparation = [](const std::string& stem) {
        const LensSystem lens = loadBundledLens(stem);
        DiagramOptions options;
        options.mode = DiagramMode::Overlay;
        const DiagramPicture picture = layoutDiagram(lens, options);
        return largestSeparation(picture, fan(picture, true), picture.content.left + 2);
    };
    EXPECT_GT(rimSeparation("fisheye.10mm"), 100.0);
    EXPECT_GT(rimSeparation("fisheye.10mm"), 5 * rimSeparation("wide.22mm"));
}

}  // namespace
}  // namespace lenslab::test

namespace lenslab::test {
namespace {

// The thick lens's rays run to the rear principal plane P' and leave the front one P at the same
// height (the planes of unit magnification), then converge on the focused object: drawn to P on both
// sides, or with the heights changed, the fan would be another lens's.
TEST(ThickLensFan, ReachesPPrimeAndLeavesPAtTheSameHeight) {
    for (const char* name : {"dgauss.50mm", "telephoto.250mm", "wide.22mm"}) {
        const LensSystem lens = loadBundledLens(name);
        const double focus = 3000;
        const LensAnalysis a = analyzeLens(lens, std::nullopt, focus);
        FanSetup setup;
        setup.filmZ = a.focus.imageZThick;
        setup.fieldHeight = 0;
        setup.rays = 7;
        setup.endZ = lens.frontZ() + 2 * focus;
        int checked = 0;
        for (const FanRay& r : traceRayFans(a, RayModel::Thick, setup)) {
            if (r.blocked) continue;
            ASSERT_GE(r.points.size(), 4u) << name;
            EXPECT_NEAR(r.points[1].z, a.thick.zPPrime, 1e-9) << name;
            EXPECT_NEAR(r.points[2].z, a.thick.zP, 1e-9) << name;
            EXPECT_NEAR(r.points[2].y, r.points[1].y, 1e-9) << name;
            // Beyond P the ray heads for the axial object point at the plane of focus.
            const ZY p = r.points[2], q = r.points[3];
            const double yAtObject = p.y + (q.y - p.y) * (lens.frontZ() + focus - p.z) / (q.z - p.z);
            EXPECT_NEAR(yAtObject, 0, 1e-6 * focus) << name;
            ++checked;
        }
        EXPECT_GE(checked, 5) << name;
    }
}

}  // namespace
}  // namespace lenslab::test
