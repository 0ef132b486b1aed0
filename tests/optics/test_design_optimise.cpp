// Optimisation (optics/design): damped least squares against optima computed here independently
// (the bending of least spherical aberration by a y-nu Seidel sum, a thin achromat's closed-form
// powers), the Cooke triplet brought back from a 5% perturbation of every curvature, the merit's
// operands against the designer's analysis, and lenses at their limits.
#include <gtest/gtest.h>

#include <cmath>

#include "DesignRows.h"
#include "ParaxialYNu.h"
#include "analysis/LensDesignAnalysis.h"
#include "design/DampedLeastSquares.h"
#include "design/GlobalSearch.h"
#include "firstorder/FirstOrder.h"
#include "prescription/OpticsError.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

constexpr double kN = 1.5;

// A singlet behind a stop of diameter epd (object at infinity): stop, r1, glass t, r2, image gap.
LensTable singletTable(double c1, double c2, double t, double epd, double n = kN) {
    return tableOfRows({stopRow(0.5, epd), openRow(c1 == 0 ? 0 : 1 / c1, t, n), openRow(c2 == 0 ? 0 : 1 / c2, 95, 0)});
}

MeritOperand operand(OperandKind kind, double target = 0, double weight = 1) {
    MeritOperand op;
    op.kind = kind;
    op.target = target;
    op.weight = weight;
    return op;
}

// The third-order spherical aberration sum S_I = -sum A^2 y delta(u/n) of the marginal ray at height
// y0, by the y-nu trace written for the tests (its refraction and transfer, not lenslab's).
double seidelSphericalSum(const LensTable& table, double y0) {
    const LensSystem lens = buildLensSystem(table);
    const std::vector<YNuSurface> sys = ynuSystem(lens, 0, int(lens.surfaces.size()), false);
    double y = y0, u = 0, n = 1, s = sys.front().s, sum = 0;
    for (const YNuSurface& k : sys) {
        y += (k.s - s) * u;
        s = k.s;
        const double a = n * (u + y * k.curvature);
        const double uAfter = (n * u - y * (k.nAfter - k.nBefore) * k.curvature) / k.nAfter;
        sum -= a * a * y * (uAfter / k.nAfter - u / n);
        n = k.nAfter;
        u = uAfter;
    }
    return sum;
}

// The rear curvature that gives a thick singlet of front curvature c1 the power 1/f:
// phi = (n - 1) (c1 - c2) + (n - 1)^2 t c1 c2 / n, solved for c2.
double rearCurvatureFor(double c1, double f, double t) {
    const double k = kN - 1;
    return (c1 - 1 / (f * k)) / (1 - k * t * c1 / kN);
}

}  // namespace

TEST(DampedLeastSquares, BendsASingletToTheSeidelMinimumOfSphericalAberration) {
    constexpr double f = 100, t = 2, epd = 5;
    // The test's own optimum: |S_I| least over the bending at fixed power (golden section in c1).
    const auto si2 = [&](double c1) {
        const double s = seidelSphericalSum(singletTable(c1, rearCurvatureFor(c1, f, t), t, epd), epd / 2);
        return s * s;
    };
    double lo = 0.0, hi = 0.04;
    for (int i = 0; i < 200; ++i) {
        const double a = hi - 0.618034 * (hi - lo), b = lo + 0.618034 * (hi - lo);
        (si2(a) < si2(b) ? hi : lo) = si2(a) < si2(b) ? b : a;
    }
    const double c1Seidel = 0.5 * (lo + hi);
    // Coddington's thin-lens shape factor for the same minimum, as a sanity check of the sum itself.
    const double c2Seidel = rearCurvatureFor(c1Seidel, f, t);
    EXPECT_NEAR((c1Seidel + c2Seidel) / (c1Seidel - c2Seidel), 2 * (kN * kN - 1) / (kN + 2), 0.02);

    DesignProblem p;
    p.start = singletTable(0.01, -0.01, t, epd);  // equiconvex: far from the best form
    p.start.wavelengths = {kWavelengthD};
    p.variables = {{VariableKind::Curvature, 1}, {VariableKind::Curvature, 2}};
    p.rules.marginalRayImageSolve = true;
    p.merit.wavelengths = {kWavelengthD};
    p.merit.operands = {operand(OperandKind::RmsSpot), operand(OperandKind::EffectiveFocalLength, f)};
    // The bending runs along a curved valley (the focal length held): each step bent along it.
    OptimiserOptions options;
    options.relativeTolerance = 1e-5;
    options.geodesicAcceleration = true;
    const OptimiserResult r = optimiseDampedLeastSquares(p, options);
    ASSERT_TRUE(r.end.valid) << r.end.problem;
    EXPECT_LT(r.end.merit, 0.5 * r.start.merit);
    const double c1 = r.values[0], c2 = r.values[1];
    EXPECT_NEAR(c1, c1Seidel, 2e-3 * c1Seidel) << "c2 " << c2 << " Seidel c2 " << c2Seidel;
    EXPECT_NEAR(r.end.values[1], f, 1e-3);
    // The image solve followed the bending: the image lies at the paraxial focus.
    const LensSystem lens = buildLensSystem(r.lens);
    EXPECT_NEAR(lens.rearZ() - r.lens.rows.back().gap, computeFirstOrder(lens).zFPrime, 1e-9);
}

TEST(DampedLeastSquares, SplitsAThinAchromatsPowerByTheClosedForm) {
    // Crown and flint as model glasses; thin elements in contact: phi1 = phi V1 / (V1 - V2),
    // phi2 = -phi V2 / (V1 - V2) is the only split with no primary axial colour.
    constexpr double n1 = 1.5168, v1 = 64.17, n2 = 1.62004, v2 = 36.37, f = 100, t = 0.01;
    DesignProblem p;
    p.start = tableOfRows({stopRow(0.5, 1.0), openRow(50, t, n1, v1), openRow(-50, t, n2, v2), openRow(0, 100, 0)});
    p.variables = {{VariableKind::Curvature, 1}, {VariableKind::Curvature, 2}, {VariableKind::Curvature, 3}};
    p.merit.operands = {operand(OperandKind::EffectiveFocalLength, f), operand(OperandKind::AxialColour, 0, 1e4)};
    const OptimiserResult r = optimiseDampedLeastSquares(p);
    ASSERT_TRUE(r.end.valid) << r.end.problem;
    EXPECT_LT(r.end.merit, 1e-14) << stopReasonText(r.stop);
    const double phi1 = (n1 - 1) * (r.values[0] - r.values[1]), phi2 = (n2 - 1) * (r.values[1] - r.values[2]);
    EXPECT_NEAR(phi1, v1 / (v1 - v2) / f, 1e-3 * phi1);
    EXPECT_NEAR(phi2, -v2 / (v1 - v2) / f, 1e-3 * std::fabs(phi2));
    EXPECT_NEAR(r.end.values[0], f, 1e-6);
}

TEST(DampedLeastSquares, BringsThePerturbedCookeTripletBackToItsDesignMerit) {
    const LensTable nominal = readLensTable(cookeTripletPath());
    MeritFunction merit;
    merit.wavelengths = nominal.wavelengths;
    for (double field : {0.0, 14.0, 20.0}) {
        MeritOperand spot = operand(OperandKind::RmsSpot);
        spot.fieldDegrees = field;
        merit.operands.push_back(spot);
    }
    merit.operands.push_back(operand(OperandKind::EffectiveFocalLength, 50));
    DesignProblem p;
    p.start = nominal;
    p.merit = merit;
    for (int row : {0, 1, 2, 3, 4, 5}) p.variables.push_back({VariableKind::Curvature, row});
    const MeritEvaluation design = evaluateMerit(nominal, merit);
    ASSERT_TRUE(design.valid) << design.problem;
    for (int k = 0; k < 6; ++k) {
        LensTableRow& r = p.start.rows[k];
        r.radius /= k % 2 == 0 ? 1.05 : 0.95;  // curvature 5% off, alternately + and -
    }
    const OptimiserResult r = optimiseDampedLeastSquares(p);
    ASSERT_TRUE(r.end.valid) << r.end.problem;
    EXPECT_GT(r.start.merit, 10 * design.merit);
    EXPECT_LE(r.end.merit, design.merit) << stopReasonText(r.stop) << " after " << r.evaluations << " evaluations";
    EXPECT_NEAR(r.end.values[3], 50, 1e-3);
    for (std::size_t k = 1; k < r.history.size(); ++k) EXPECT_LT(r.history[k], r.history[k - 1]);
}

DesignAnalysisInputs tripletAnalysisInputs(const LensTable& table, double stopDiameter) {
    DesignAnalysisInputs in;
    in.lens.stopDiameter = Setting{stopDiameter, "test"};
    in.wavelengths = table.wavelengths;
    in.fields = {0, 14, 20};
    in.fieldsInDegrees = true;
    in.imagePlane = ImagePlane::Paraxial;
    return in;
}

// The merit's spots are the analysis's: the same rays, sampling, image plane and centroid. The stop
// is closed to 5 mm, well inside the widest the analysis opens it to.
TEST(MeritFunction, SpotsAndFocalLengthEqualTheDesignersAnalysis) {
    const LensTable table = withStopDiameter(readLensTable(cookeTripletPath()), 5);
    MeritFunction merit;
    merit.wavelengths = table.wavelengths;
    merit.imagePlane = MeritImagePlane::Paraxial;
    merit.settle = true;
    for (double field : {0.0, 14.0, 20.0}) {
        MeritOperand spot = operand(OperandKind::RmsSpot);
        spot.fieldDegrees = field;
        merit.operands.push_back(spot);
        spot.wavelength = table.wavelengths[0];
        merit.operands.push_back(spot);
    }
    merit.operands.push_back(operand(OperandKind::EffectiveFocalLength));
    const MeritEvaluation e = evaluateMerit(table, merit);
    ASSERT_TRUE(e.valid) << e.problem;
    const LensSystem lens = buildLensSystem(table);
    const LensDesignAnalysis a = analyzeLensDesign(lens, tripletAnalysisInputs(table, 5));
    ASSERT_NEAR(a.lens.lens.stop().apertureRadius, 2.5, 1e-12);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(e.values[2 * k], a.fields[k].polychromatic.rmsRadius, 1e-12) << "field " << k;
        EXPECT_NEAR(e.values[2 * k + 1], a.fields[k].spots[0].statistics.rmsRadius, 1e-12) << "field " << k;
    }
    EXPECT_NEAR(e.values[6], computeFirstOrder(lens).efl, 1e-12);
}

TEST(DampedLeastSquares, KeepsEveryStepValidAtTheLimits) {
    // An f/1 singlet (n 1.8, plano-convex, 100 mm) asked for a spot it cannot have and for glass of
    // no thickness: steps into total internal reflection of the marginal ray or into crossing
    // surfaces are refused; the lens at the end is valid and finite.
    DesignProblem p;
    p.start = singletTable(1 / 80.0, 0, 25, 100, 1.8);
    p.start.wavelengths = {kWavelengthD};
    p.variables = {{VariableKind::Curvature, 1}, {VariableKind::Curvature, 2}, {VariableKind::Thickness, 1}};
    p.merit.wavelengths = {kWavelengthD};
    MeritOperand thin = operand(OperandKind::CentreThickness, 0, 10);
    thin.row = 1;
    p.merit.operands = {operand(OperandKind::RmsSpot), operand(OperandKind::EffectiveFocalLength, 100), thin};
    const MeritEvaluation start = evaluateMerit(p.start, p.merit);
    ASSERT_TRUE(start.valid) << start.problem;
    const OptimiserResult r = optimiseDampedLeastSquares(p);
    ASSERT_TRUE(r.end.valid) << r.end.problem;
    for (double v : r.values) EXPECT_TRUE(std::isfinite(v));
    EXPECT_LT(r.end.merit, r.start.merit);
    EXPECT_TRUE(evaluateMerit(r.lens, p.merit).valid);
    EXPECT_GT(r.values[2], 0);
    // Thinner glass is what the merit asks for, so the search ends against the edge: a lens thinner
    // still crosses its surfaces or loses its marginal ray, and is refused.
    std::vector<double> thinner = r.values;
    thinner[2] -= 2;
    const MeritEvaluation crossed = evaluateDesign(p, thinner);
    EXPECT_FALSE(crossed.valid);
    EXPECT_TRUE(crossed.problem.find("cross") != std::string::npos || crossed.problem.find("marginal ray") != std::string::npos)
        << crossed.problem;
    // A curvature driven through flat: a concave front (f 133 mm) must turn convex for f 80 mm.
    DesignProblem flat;
    flat.start = singletTable(-0.005, -0.02, 3, 10);
    flat.start.wavelengths = {kWavelengthD};
    flat.variables = {{VariableKind::Curvature, 1}};
    flat.merit.wavelengths = {kWavelengthD};
    flat.merit.operands = {operand(OperandKind::EffectiveFocalLength, 80)};
    const OptimiserResult through = optimiseDampedLeastSquares(flat);
    ASSERT_TRUE(through.end.valid) << through.end.problem;
    EXPECT_NEAR(through.end.values[0], 80, 1e-6);
    // The thick-lens power (n - 1)(c1 - c2) + (n - 1)^2 t c1 c2 / n = 1/80 solved for c1.
    const double k = kN - 1, c2 = -0.02;
    EXPECT_NEAR(through.values[0], (1 / 80.0 + k * c2) / (k + k * k * 3 * c2 / kN), 1e-8);
}

TEST(DampedLeastSquares, SaysWhenTheMeritCannotImprove) {
    // The image distance changes no focal length: the Jacobian is zero and no step lowers the merit.
    DesignProblem p;
    p.start = singletTable(0.02, -0.02, 3, 10);
    p.variables = {{VariableKind::Thickness, 2}};
    p.merit.operands = {operand(OperandKind::EffectiveFocalLength, 10)};
    const OptimiserResult r = optimiseDampedLeastSquares(p);
    EXPECT_EQ(r.stop, StopReason::CannotImprove);
    EXPECT_EQ(r.end.merit, r.start.merit);
    EXPECT_EQ(r.values[0], 95);
    // A starting lens that is not valid is refused with its reason.
    DesignProblem crossed = p;
    crossed.start.rows[1].gap = -1;
    EXPECT_THROW(optimiseDampedLeastSquares(crossed), OpticsError);
    // A variable that does not apply is refused by name.
    DesignProblem wrong = p;
    wrong.variables = {{VariableKind::Index, 2}};
    EXPECT_THROW(optimiseDampedLeastSquares(wrong), std::invalid_argument);
}

TEST(GlobalSearch, IsReproducibleFromItsSeedAndNeverWorseThanOneDescent) {
    DesignProblem p;
    p.start = singletTable(0.01, -0.01, 2, 5);
    p.start.wavelengths = {kWavelengthD};
    p.variables = {{VariableKind::Curvature, 1}, {VariableKind::Curvature, 2}};
    p.rules.marginalRayImageSolve = true;
    p.merit.wavelengths = {kWavelengthD};
    p.merit.operands = {operand(OperandKind::RmsSpot), operand(OperandKind::EffectiveFocalLength, 100)};
    GlobalSearchOptions options;
    options.hops = 3;
    options.seed = 42;
    const GlobalSearchResult a = searchGlobally(p, options), b = searchGlobally(p, options);
    const OptimiserResult local = optimiseDampedLeastSquares(p);
    EXPECT_EQ(a.best.values, b.best.values);
    EXPECT_LE(a.best.end.merit, local.end.merit);
    EXPECT_GT(a.evaluations, local.evaluations);
}
