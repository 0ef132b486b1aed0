// Tolerancing (optics/design): departures applied where and in the direction they say (checked by
// their effect on the image: a decentred element moves the image with it, a glass's index moves by
// its tolerance), the Monte Carlo's draws and percentiles, and each trial's numbers against an
// analysis of the same as-built lens made independently (the designer's analysis, a y-nu trace).
#include <gtest/gtest.h>

#include <cmath>

#include "DesignRows.h"
#include "ParaxialYNu.h"
#include "analysis/LensDesignAnalysis.h"
#include "design/GlassSnap.h"
#include "design/ToleranceAnalysis.h"
#include "firstorder/FirstOrder.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {


// The effective focal length by the test's own y-nu trace: a ray parallel to the axis at height 1
// leaves with slope u; f = -1 / u.
double ynuFocalLength(const LensSystem& lens) {
    const YNu out = traceYNu(ynuSystem(lens, 0, int(lens.surfaces.size()), false), lens.surfaces.front().z * -1, 1, 0);
    return -1 / out.u;
}

// Where the on-axis bundle's centroid lands on the plane z (primary wavelength, object at infinity).
Point2 axialCentroid(const LensSystem& lens, double z) {
    const std::optional<FieldAim> aim = aimField(lens, {0, kInf});
    const ImageRays rays = settledImageRays(lens, *aim, z, {}, 0.002, 64);
    std::vector<Point2> points;
    for (std::size_t i = 0; i < rays.at.size(); ++i) points.push_back(rays.pointOn(i, z));
    return spotStatistics(points, rays.weight).centroid;
}

ToleranceProblem tripletProblem(MeritImagePlane plane) {
    ToleranceProblem p;
    p.nominal = withStopDiameter(readLensTable(cookeTripletPath()), 5);
    p.merit.wavelengths = p.nominal.wavelengths;
    p.merit.imagePlane = plane;
    for (double field : {0.0, 14.0, 20.0}) {
        MeritOperand spot;
        spot.fieldDegrees = field;
        p.merit.operands.push_back(spot);
    }
    MeritOperand efl;
    efl.kind = OperandKind::EffectiveFocalLength;
    efl.target = 50;
    p.merit.operands.push_back(efl);
    ToleranceSpec spec;
    spec.radiusFraction = 0.001;
    spec.thickness = 0.02;
    spec.decentre = 0.01;
    spec.tilt = 0.01;
    spec.index = 5e-4;
    p.tolerances = expandTolerances(p.nominal, spec);
    return p;
}

}  // namespace

TEST(Distribution, PercentilesInterpolateTheOrderStatistics) {
    std::vector<double> values;
    for (int k = 100; k >= 0; --k) values.push_back(k);
    const Distribution d = distributionOf(values, 10);
    EXPECT_EQ(d.count, 101);
    EXPECT_DOUBLE_EQ(d.mean, 50);
    EXPECT_DOUBLE_EQ(d.p50, 50);
    EXPECT_DOUBLE_EQ(d.p90, 90);
    EXPECT_DOUBLE_EQ(d.p98, 98);
    EXPECT_EQ(d.min, 0);
    EXPECT_EQ(d.max, 100);
    int total = 0;
    for (int c : d.histogram) total += c;
    EXPECT_EQ(total, 101);
    EXPECT_EQ(d.histogram.front(), 10);
    EXPECT_EQ(d.histogram.back(), 11);  // the maximum falls in the last bin
    EXPECT_DOUBLE_EQ(distributionOf({1, 2}).p90, 1.9);
}

TEST(ToleranceDraw, DrawsAreSeededBoundedAndOfTheStatedSpread) {
    ToleranceProblem p;
    p.tolerances = {{ToleranceKind::Thickness, 0, 0, 0.02}};
    for (ToleranceDraw draw : {ToleranceDraw::Uniform, ToleranceDraw::Normal}) {
        double sum2 = 0;
        constexpr int n = 40000;
        for (int k = 0; k < n; ++k) {
            const double d = drawDepartures(p, draw, 9, k)[0];
            ASSERT_LE(std::fabs(d), 0.02);
            sum2 += d * d;
        }
        // Uniform: limit / sqrt 3. Normal with sigma limit / 2 truncated at 2 sigma: 0.8796 sigma.
        const double expected = draw == ToleranceDraw::Uniform ? 0.02 / std::sqrt(3.0) : 0.01 * 0.87963;
        EXPECT_NEAR(std::sqrt(sum2 / n), expected, 0.01 * expected);
    }
    EXPECT_EQ(drawDepartures(p, ToleranceDraw::Normal, 3, 17), drawDepartures(p, ToleranceDraw::Normal, 3, 17));
    EXPECT_NE(drawDepartures(p, ToleranceDraw::Normal, 3, 17), drawDepartures(p, ToleranceDraw::Normal, 4, 17));
}

TEST(Tolerance, DeparturesMoveTheLensAsTheyName) {
    // A singlet behind its stop: decentring the element moves the image of a star on the axis with
    // it (its focal point lies on its own axis), by the decentre, in its direction.
    const LensTable table = tableOfRows({stopRow(2, 1), openRow(60, 3, 1.5), openRow(-60, 58, 0)});
    const LensSystem nominal = buildLensSystem(table);
    const double focusZ = computeFirstOrder(nominal).zFPrime;
    const std::vector<Tolerance> element = {{ToleranceKind::ElementDecentreX, 1, 2, 0.05},
                                            {ToleranceKind::ElementDecentreY, 1, 2, 0.05}};
    for (const Point2 d : {Point2{0.03, 0}, Point2{0, -0.02}, Point2{0.01, 0.04}}) {
        const LensSystem moved = buildLensSystem(perturbedLens(table, element, {d.x, d.y}));
        const Point2 c = axialCentroid(moved, focusZ);
        EXPECT_NEAR(c.x, d.x, 0.01 * 0.05) << d.x << " " << d.y;  // less the coma the decentre brings
        EXPECT_NEAR(c.y, d.y, 0.01 * 0.05) << d.x << " " << d.y;
        // The surfaces after the element are back on the axis: the focal length is unchanged.
        EXPECT_NEAR(ynuFocalLength(moved), ynuFocalLength(nominal), 1e-9);
    }
    // A surface's own decentre moves that surface alone: the rear surface decentred by d is a wedge,
    // which deviates the beam by (n - 1) d / R toward the decentre (a prism of that angle).
    const std::vector<Tolerance> rear = {{ToleranceKind::DecentreY, 2, 0, 0.05}};
    const LensSystem wedge = buildLensSystem(perturbedLens(table, rear, {0.04}));
    const Point2 c = axialCentroid(wedge, focusZ);
    EXPECT_NEAR(c.y, 0.04 * 0.5 / 60 * (nominal.rearZ() - focusZ), 0.02 * 0.04 * 0.5 / 60 * 58);
    // Radius, thickness and index departures, in their units.
    const std::vector<Tolerance> others = {{ToleranceKind::Radius, 1, 0, 0.001}, {ToleranceKind::Thickness, 1, 0, 0.02},
                                           {ToleranceKind::Index, 1, 0, 5e-4}};
    const LensTable built = perturbedLens(table, others, {-0.001, 0.02, 5e-4});
    EXPECT_DOUBLE_EQ(built.rows[1].radius, 60 * 0.999);
    EXPECT_DOUBLE_EQ(built.rows[1].gap, 3.02);
    EXPECT_DOUBLE_EQ(built.rows[1].index, 1.5005);
}

TEST(Tolerance, AGlassDepartureMovesItsIndexAndAbbeNumber) {
    LensTable table = readLensTable(cookeTripletPath());
    const std::vector<Tolerance> glass = {{ToleranceKind::Index, 2, 0, 5e-4}, {ToleranceKind::Abbe, 2, 0, 0.5}};
    const LensSystem nominal = buildLensSystem(table);
    const LensSystem built = buildLensSystem(perturbedLens(table, glass, {4e-4, -0.3}));
    const Medium& before = nominal.surfaces[2].mediumAfter;  // F2, after the third surface
    const Medium& after = built.surfaces[2].mediumAfter;
    EXPECT_NEAR(refractiveIndex(after, kWavelengthD) - refractiveIndex(before, kWavelengthD), 4e-4, 1e-6);
    EXPECT_NEAR(abbeNumber(after), abbeNumber(before) - 0.3, 2e-3);
    // Between the d line and each wavelength the dispersion is scaled so that Vd moves by its own
    // departure once nd has moved by its own: (nd + dn - 1) / (nd - 1) x Vd / (Vd + dv).
    const double nd = refractiveIndex(before, kWavelengthD), vd = abbeNumber(before);
    const double scale = (nd + 4e-4 - 1) / (nd - 1) * vd / (vd - 0.3);
    for (double nm : {480.0, 550.0, 650.0}) {
        const double shift = refractiveIndex(after, nm) - refractiveIndex(before, nm);
        const double dispersion = refractiveIndex(before, nm) - nd;
        EXPECT_NEAR(shift, 4e-4 + dispersion * (scale - 1), 2e-7) << nm;
    }
}

// Each Monte Carlo trial measures the lens its departures make: the same numbers as the designer's
// analysis of that lens (spots) and the test's own y-nu trace (focal length).
TEST(MonteCarlo, EachTrialMeasuresItsAsBuiltLens) {
    ToleranceProblem p = tripletProblem(MeritImagePlane::Paraxial);
    p.merit.settle = true;
    MonteCarloOptions options;
    options.trials = 6;
    options.seed = 11;
    const MonteCarloResult mc = runMonteCarlo(p, options);
    ASSERT_EQ(mc.invalid, 0);
    for (int k = 0; k < options.trials; ++k) {
        const ToleranceTrial& t = mc.trials[k];
        EXPECT_EQ(t.departures, drawDepartures(p, options.draw, options.seed, k));
        const LensSystem lens = buildLensSystem(asBuiltLens(p, t.departures));
        DesignAnalysisInputs in;
        in.lens.stopDiameter = Setting{5, "test"};  // the table's stop: well inside the widest the analysis opens
        in.wavelengths = p.merit.wavelengths;
        in.fields = {0, 14, 20};
        in.fieldsInDegrees = true;
        in.imagePlane = ImagePlane::Paraxial;
        const LensDesignAnalysis a = analyzeLensDesign(lens, in);
        ASSERT_NEAR(a.lens.lens.stop().apertureRadius, 2.5, 1e-12);
        for (int f = 0; f < 3; ++f) EXPECT_NEAR(t.evaluation.values[f], a.fields[f].polychromatic.rmsRadius, 1e-9) << k << " " << f;
        EXPECT_NEAR(t.evaluation.values[3], ynuFocalLength(lens), 1e-4) << k;  // y-nu sees no decentre (second order)
    }
    EXPECT_EQ(mc.operands.size(), 4u);
    EXPECT_EQ(mc.operands[0].count, options.trials);
    EXPECT_DOUBLE_EQ(mc.yield, 1.0);
}

TEST(MonteCarlo, TheBackFocusCompensatorRefocusesEveryTrial) {
    ToleranceProblem p = tripletProblem(MeritImagePlane::Table);
    const MonteCarloResult fixed = runMonteCarlo(p, [] {
        MonteCarloOptions o;
        o.trials = 8;
        o.seed = 5;
        return o;
    }());
    p.compensators = {{VariableKind::Thickness, 5}};  // the image distance
    MonteCarloOptions options;
    options.trials = 8;
    options.seed = 5;
    options.specification = {{0, OperandBound::AtMost, 1e-9}};  // no real lens meets it: yield 0
    const MonteCarloResult compensated = runMonteCarlo(p, options);
    for (int k = 0; k < 8; ++k) {
        ASSERT_TRUE(compensated.trials[k].evaluation.valid);
        EXPECT_LE(compensated.trials[k].evaluation.merit, fixed.trials[k].evaluation.merit * (1 + 1e-9)) << k;
        EXPECT_NE(compensated.trials[k].compensators[0], 42.20778) << k;
    }
    EXPECT_EQ(compensated.yield, 0.0);
    EXPECT_LE(compensated.merit.p90, fixed.merit.p90);
    const std::optional<int> worst = trialAtPercentile(compensated, 100);
    ASSERT_TRUE(worst);
    EXPECT_DOUBLE_EQ(compensated.trials[*worst].evaluation.merit, compensated.merit.max);
}

TEST(Sensitivity, EachToleranceAloneAtBothLimitsRankedByItsEffect) {
    ToleranceProblem p = tripletProblem(MeritImagePlane::Paraxial);
    p.tolerances = {{ToleranceKind::Radius, 0, 0, 0.001}, {ToleranceKind::Thickness, 1, 0, 0.02},
                    {ToleranceKind::TiltX, 4, 0, 0.05}, {ToleranceKind::Index, 4, 0, 5e-4}};
    const std::vector<SensitivityRow> rows = toleranceSensitivity(p);
    ASSERT_EQ(rows.size(), 4u);
    for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_GE(rows[k - 1].meritChange, rows[k].meritChange);
    for (const SensitivityRow& row : rows) {
        for (double sign : {1.0, -1.0}) {
            const LensSystem lens = buildLensSystem(perturbedLens(p.nominal, {row.tolerance}, {sign * row.tolerance.limit}));
            const MeritEvaluation& e = sign > 0 ? row.plus : row.minus;
            ASSERT_TRUE(e.valid);
            // The y-nu trace sees no tilt: a tilt's own effect on the focal length is of second order.
            const bool tilted = row.tolerance.kind == ToleranceKind::TiltX;
            EXPECT_NEAR(e.values[3], ynuFocalLength(lens), tilted ? 1e-4 : 1e-8) << describeTolerance(row.tolerance);
        }
    }
    // A tilt leaves the focal length, to first order; a radius changes it.
    const auto rowOf = [&](ToleranceKind kind) {
        return *std::find_if(rows.begin(), rows.end(), [&](const SensitivityRow& r) { return r.tolerance.kind == kind; });
    };
    EXPECT_GT(std::fabs(rowOf(ToleranceKind::Radius).plus.values[3] - 50.0), 1e-3);
}

// A cancelled sensitivity run stops between rows: the service's DELETE and SIGTERM waited 20 s for
// dgauss.50mm's hundred tolerances while every row still evaluated its lens.
TEST(Sensitivity, ACancelledRunMeasuresNoFurtherRow) {
    ToleranceProblem p = tripletProblem(MeritImagePlane::Paraxial);
    p.tolerances = {{ToleranceKind::Radius, 0, 0, 0.001}, {ToleranceKind::Thickness, 1, 0, 0.02},
                    {ToleranceKind::TiltX, 4, 0, 0.05}, {ToleranceKind::Index, 4, 0, 5e-4}};
    OptimiserOptions compensation = compensatorSearch();
    compensation.cancelled = [] { return true; };
    const std::vector<SensitivityRow> rows = toleranceSensitivity(p, compensation);
    ASSERT_EQ(rows.size(), 4u);
    for (const SensitivityRow& row : rows) {
        EXPECT_FALSE(row.plus.valid) << describeTolerance(row.tolerance);
        EXPECT_FALSE(row.minus.valid) << describeTolerance(row.tolerance);
    }
}

TEST(GlassSnap, AModelGlassBecomesItsNearestCatalogGlass) {
    // Schott's N-BK7 is 1.5168 / 64.17 and F2 1.62004 / 36.37: a model glass a little off each
    // snaps to it (not to P-BK7, 1.5164 / 64.06, nor N-F2, 1.62005 / 36.43, each farther on the
    // map's scale); air stays. 1.5170 / 64.0 is nearer P-BK7.
    EXPECT_EQ(nearestCatalogGlass(1.5168, 64.17, {"SCHOTT"})->name, "N-BK7");
    EXPECT_EQ(nearestCatalogGlass(1.5170, 64.0, {"SCHOTT"})->name, "P-BK7");
    LensTable table = tableOfRows({stopRow(1, 10), openRow(60, 4, 1.5168, 64.2), openRow(-40, 2, 1.6200, 36.36), openRow(-200, 90, 0)});
    table.rows[0].glass = "";
    const std::vector<GlassChoice> choices = snapToCatalogGlasses(table, {1, 2, 3}, {"SCHOTT"});
    ASSERT_EQ(choices.size(), 2u);
    EXPECT_EQ(table.rows[1].glass, "N-BK7");
    EXPECT_EQ(table.rows[2].glass, "F2");
    EXPECT_EQ(table.rows[2].glassCatalog, "SCHOTT");
    EXPECT_NEAR(choices[0].distance, std::hypot(100 * (1.5168 - 1.5168), 64.17 - 64.2), 1e-9);
    EXPECT_TRUE(table.rows[3].glass.empty());  // air
    // The snapped table builds with the catalog's glasses.
    const LensSystem lens = buildLensSystem(table);
    EXPECT_NEAR(refractiveIndex(lens.surfaces[1].mediumAfter, kWavelengthD), 1.5168, 1e-5);
}
