// The largest field (docs/analysis.md, "Fields"): where a rim stops the chief ray, against the
// geometry written here; a lens whose apertures never stop it has none; an obscured system's field
// is its rims', not its obscuration's; the lateral colour is measured there or not at all.
#include <gtest/gtest.h>

#include <cmath>

#include "firstorder/FieldOfView.h"
#include "settings/LensAnalysis.h"
#include "PrescriptionRows.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {


}  // namespace

TEST(FieldOfView, ARearRimStopsTheChiefRayWhereTheGeometrySays) {
    // The stop, then L of air to a flat window of radius a (index 1 on both sides: it bends no ray),
    // then a wide lens. The chief ray crosses the stop's centre undeviated, so it meets the window at
    // L tan theta: the field ends at atan(a / L).
    const double L = 20, a = 6;
    const LensSystem lens = buildRows({stopRow(L, 10), row(0, 1, 0, 2 * a), row(80, 10, 1.5, 40), row(-80, 0, 0, 40)});
    const FieldOfView fov = lensFieldOfView(lens);
    ASSERT_TRUE(fov.largestDegrees) << fov.source;
    EXPECT_NEAR(*fov.largestDegrees, std::atan(a / L) * 180 / M_PI, 1e-6);
    EXPECT_NE(fov.source.find("chief ray"), std::string::npos);
}

TEST(FieldOfView, ALensThatNeverStopsTheChiefRayHasNone) {
    // The Thorlabs doublet's stop sits on its first face: every chief ray passes, up to 89 degrees.
    const LensAnalysis a = analyzeLens(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/ac254-100-a.dat"), std::nullopt, kInf);
    EXPECT_FALSE(a.field.largestDegrees);
    EXPECT_NE(a.field.source.find("none"), std::string::npos);
    EXPECT_FALSE(a.chromatic.lateral);  // no field, no lateral colour at 85 degrees
}

TEST(FieldOfView, AnObscuredLensKeepsTheFieldItsRimsAllow) {
    // The reflex lens's secondary mirror blocks the chief ray on axis; its field is still its rims'
    // (its file's own list, 2.5 degrees at most, set aside to measure them).
    LensSystem reflex = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us4666259-ex1-reflex-500mm.zmx");
    EXPECT_DOUBLE_EQ(*lensFieldOfView(reflex).largestDegrees, 2.5);
    reflex.fields.points.clear();
    const FieldOfView fov = lensFieldOfView(reflex);
    ASSERT_TRUE(fov.largestDegrees) << fov.source;
    EXPECT_GT(*fov.largestDegrees, 2.5);  // the patent's 2w = 5 degrees pass
    EXPECT_LT(*fov.largestDegrees, 5);
    // Just inside the field its chief ray passes every clear aperture; just outside, one stops it.
    const double z = analyzeLens(reflex, std::nullopt, kInf).firstOrder.zFPrime;
    EXPECT_TRUE(chiefRayHeight(reflex, *fov.largestDegrees * 0.999, z, true));
    EXPECT_FALSE(chiefRayHeight(reflex, *fov.largestDegrees * 1.001, z, true));
}

TEST(FieldOfView, LateralColourIsMeasuredAtTheLargestField) {
    const LensAnalysis a =
        analyzeLens(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us2010-0033848-ex1-35mm.zmx"), std::nullopt, kInf);
    ASSERT_TRUE(a.field.largestDegrees);
    ASSERT_TRUE(a.chromatic.lateral);
    EXPECT_DOUBLE_EQ(a.chromatic.lateral->fieldDegrees, *a.field.largestDegrees);
    // A lens without dispersion has none to measure: 0, at the same field.
    const LensAnalysis plain = analyzeLens(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat"), std::nullopt, kInf);
    ASSERT_TRUE(plain.chromatic.lateral);
    EXPECT_EQ(plain.chromatic.lateral->mm, 0);
    EXPECT_DOUBLE_EQ(plain.chromatic.lateral->fieldDegrees, *plain.field.largestDegrees);
}

// A prescription's own field list comes first (docs/analysis.md, "Fields"): its largest point as an
// object angle, whatever form the file states it in. dgauss.50mm (EFL 50.3582 mm, its rims allow
// about 29 degrees) with a list added.
TEST(FieldOfView, ThePrescriptionsFieldListComesFirstInEveryForm) {
    LensSystem lens = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat");
    const FirstOrder fo = analyzeLens(lens, std::nullopt, kInf).firstOrder;
    const double rims = *lensFieldOfView(lens).largestDegrees;
    EXPECT_GT(rims, 25);
    constexpr double kDeg = 180 / M_PI;

    lens.fields = {FieldType::ObjectAngle, {{0, 0, 1}, {3, 4, 1}, {0, 2, 1}}};  // the largest: 5 degrees
    FieldOfView fov = lensFieldOfView(lens);
    EXPECT_DOUBLE_EQ(*fov.largestDegrees, 5);
    EXPECT_EQ(fov.source, "the prescription's field list: 5 deg object angle");

    // A paraxial image height h of a distant object: tan(field) = h / EFL.
    lens.fields = {FieldType::ParaxialImageHeight, {{0, 0, 1}, {0, 15, 1}}};
    EXPECT_NEAR(*lensFieldOfView(lens).largestDegrees, std::atan(15 / fo.efl) * kDeg, 1e-12);

    // A real image height: the field whose traced chief ray lands 15 mm off axis on the focal plane.
    // The double Gauss's barrel distortion puts it beyond the paraxial field.
    lens.fields = {FieldType::RealImageHeight, {{0, 0, 1}, {0, 15, 1}}};
    const double real = *lensFieldOfView(lens).largestDegrees;
    EXPECT_NEAR(std::fabs(*chiefRayHeight(lens, real, fo.zFPrime, false)), 15, 1e-9);
    EXPECT_GT(real, std::atan(15 / fo.efl) * kDeg);

    // An object height needs a near object; for a distant one the lens's rims decide.
    lens.fields = {FieldType::ObjectHeight, {{0, 0, 1}, {0, 100, 1}}};
    EXPECT_DOUBLE_EQ(*lensFieldOfView(lens).largestDegrees, rims);
    // A list with nothing off the axis is no limit either.
    lens.fields = {FieldType::ObjectAngle, {{0, 0, 1}}};
    EXPECT_DOUBLE_EQ(*lensFieldOfView(lens).largestDegrees, rims);
}
