// Stability at the extremes (issue 7): grazing, rim and axial rays, total internal reflection,
// radii from 1e-3 mm to 1e9 mm and flat surfaces, stops from 1 micrometre to fully open, f-numbers
// and focus distances at and just beyond their limits, stop first or last. Every case must give
// finite numbers or an OpticsError / LensTableError that says what is wrong: never NaN, never a hang.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "trace/ExactTrace.h"
#include "settings/LensAnalysis.h"
#include "prescription/OpticsError.h"
#include "trace/RayBatch.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

LensSystem builtTable(const std::string& text) { return buildLensSystem(parseLensTable(text, "x.dat")); }

LensSystem dgauss() { return loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"); }

// dgauss.50mm with its stop row (line 10) rewritten to the given diameter.
LensSystem dgaussWithStopRow(double diameter) {
    LensTable t = readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    for (LensTableRow& row : t.rows)
        if (row.isStop()) row.diameter = diameter;
    return buildLensSystem(t);
}

void expectOpticsError(const std::function<void()>& call, const std::string& part) {
    try {
        call();
        ADD_FAILURE() << "no OpticsError (expected one mentioning '" << part << "')";
    } catch (const OpticsError& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

void expectFiniteUnit(const Ray& r) {
    EXPECT_TRUE(isFinite(r.origin)) << r.origin.x << " " << r.origin.y << " " << r.origin.z;
    EXPECT_TRUE(isFinite(r.direction));
    EXPECT_NEAR(length(r.direction), 1.0, 1e-12);
}

void expectAllFinite(const LensAnalysis& a) {
    const FirstOrder& fo = a.firstOrder;
    for (double v : {fo.efl, fo.eflFront, fo.zF, fo.zFPrime, fo.zP, fo.zPPrime, a.aperture.fstopMin,
                     a.aperture.stopDiameterMax, a.fstop, a.stopDiameter, a.pupils.entrance.z,
                     a.pupils.entrance.diameter, a.pupils.exit.z, a.pupils.exit.diameter,
                     a.focus.imageZThick, a.focus.imageZExact})
        EXPECT_TRUE(std::isfinite(v)) << v;
}

// One surface step on a bare surface at z = 0 (so the tests below read as geometry).
struct Step {
    Ray ray;
    BlockReason why;
};
template <class T = double>
Step step(Ray r, double curvature, double apertureRadius, double eta, bool isStop = false) {
    T px = T(r.origin.x), py = T(r.origin.y), pz = T(r.origin.z);
    T dx = T(r.direction.x), dy = T(r.direction.y), dz = T(r.direction.z);
    SurfaceConstants<T> s;
    s.curvature = T(curvature);
    s.radius = T(1) / T(curvature);
    s.apertureRadius2 = T(apertureRadius * apertureRadius);
    s.eta = T(eta);
    s.beyondAperture = static_cast<int>(isStop ? BlockReason::ClippedByStop : BlockReason::OutsideAperture);
    const BlockReason why = stepThroughSurface<T>(px, py, pz, dx, dy, dz, s);
    return {{{px, py, pz}, {dx, dy, dz}}, why};
}

}  // namespace

// ---- rays -------------------------------------------------------------------------------------

TEST(Extremes, AxialRayStaysExactlyOnTheAxisBothWaysAndInTheBatch) {
    const LensSystem lens = dgauss();
    const TraceResult in = traceRay(lens, {{0, 0, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    const TraceResult out = traceRay(lens, {{0, 0, lens.rearZ() - 10}, {0, 0, 1}}, TraceDirection::FilmToScene);
    ASSERT_TRUE(in.ok());
    ASSERT_TRUE(out.ok());
    EXPECT_EQ(in.ray.origin.x, 0);
    EXPECT_EQ(in.ray.origin.y, 0);
    EXPECT_EQ(in.ray.direction.z, -1);
    EXPECT_EQ(out.ray.origin.y, 0);
    EXPECT_NEAR(out.ray.origin.z, lens.frontZ(), 1e-12);
    EXPECT_EQ(out.ray.direction.z, 1);
    RayBatch batch;
    batch.resize(1);
    batch.set(0, {{0, 0, 10}, {0, 0, -1}});
    traceBatch(lens, batch, TraceDirection::SceneToFilm);
    EXPECT_EQ(batch.blocked[0], BlockReason::None);
    EXPECT_EQ(batch.oy[0], 0);
    EXPECT_EQ(batch.dz[0], -1);
}

TEST(Extremes, RimRaysPassAndTheNextDoubleOutIsBlockedWithItsReason) {
    // Flat surfaces, so the hit height is exactly the ray height: window of 20 mm, stop of 10 mm.
    const LensSystem lens = builtTable("0 0 1.5 20\n0 5 1 20\n0 5 0 10\n");
    auto trace = [&](double y) { return traceRay(lens, {{0, y, 1}, {0, 0, -1}}, TraceDirection::SceneToFilm); };
    EXPECT_TRUE(trace(5).ok());
    const TraceResult stop = trace(std::nextafter(5.0, 6.0));
    EXPECT_EQ(stop.blocked, BlockReason::ClippedByStop);
    EXPECT_EQ(stop.surface, 2);
    EXPECT_EQ(stop.ray.origin.z, -5);  // left where the last surface put it
    const TraceResult rim = trace(10);
    EXPECT_EQ(rim.blocked, BlockReason::ClippedByStop);  // passed both window surfaces at their rims
    const TraceResult outside = trace(std::nextafter(10.0, 11.0));
    EXPECT_EQ(outside.blocked, BlockReason::OutsideAperture);
    EXPECT_EQ(outside.surface, 0);
    EXPECT_STREQ(blockReasonName(outside.blocked), "outside clear aperture");

    // dgauss: a parallel ray at the front element's rim (12.6 mm) passes surface 0.
    const LensSystem d = dgauss();
    const double rim0 = d.surfaces[0].apertureRadius;
    const TraceResult atRim = traceRay(d, {{0, rim0, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    EXPECT_GT(atRim.surface, 0);
    EXPECT_NE(atRim.blocked, BlockReason::None);  // f/2 cannot take a 25 mm beam: clipped further in
    expectFiniteUnit(atRim.ray);
}

TEST(Extremes, GrazingRaysOnACurvedSurfaceStayFinite) {
    // Sphere R = 10 (centre at z = -10), clear radius 10. A ray tangent to it at 30 degrees from
    // the axis: it either touches (finite hit on the sphere) or misses, ray untouched.
    const double a = M_PI / 6;
    const Vec3 touch{0, 10 * std::sin(a), -10 + 10 * std::cos(a)};
    const Vec3 tangent{0, std::cos(a), -std::sin(a)};
    const Ray in{touch - 20.0 * tangent, tangent};
    for (double eta : {1 / 1.5, 1.5}) {
        const Step s = step(in, 0.1, 10, eta);
        expectFiniteUnit(s.ray);
        if (s.why == BlockReason::None) {
            EXPECT_NEAR(length(s.ray.origin - touch), 0, 1e-6);
        } else {
            EXPECT_TRUE(s.why == BlockReason::MissedSurface || s.why == BlockReason::TotalInternalReflection);
        }
    }
    // Nearly grazing incidence (89.99 degrees) into glass refracts to just under the critical angle.
    const double g = (90 - 1e-2) * M_PI / 180;
    const Step s = step({{0, -5 * std::sin(g), 5 * std::cos(g)}, {0, std::sin(g), -std::cos(g)}}, 0, 10, 1 / 1.5);
    ASSERT_EQ(s.why, BlockReason::None);
    EXPECT_NEAR(s.ray.direction.y, std::sin(g) / 1.5, 1e-15);  // sin(r) = sin(i) / n
    EXPECT_NEAR(s.ray.direction.y, 1 / 1.5, 1e-7);
    expectFiniteUnit(s.ray);
}

TEST(Extremes, RaysParallelToAFlatSurfaceMissInsteadOfProducingNaN) {
    // dz = 0: no intersection; on the surface plane itself the root is 0/0.
    for (double z : {1.0, 0.0}) {
        const Step s = step({{0, 1, z}, {0, 1, 0}}, 0, 10, 1 / 1.5);
        EXPECT_EQ(s.why, BlockReason::MissedSurface) << z;
        EXPECT_EQ(s.ray.origin.z, z);
        EXPECT_EQ(s.ray.direction.y, 1);
    }
    const Step f = step<float>({{0, 1, 0}, {0, 1, 0}}, 0, 10, 1 / 1.5);
    EXPECT_EQ(f.why, BlockReason::MissedSurface);
}

TEST(Extremes, TotalInternalReflectionIsReportedAndLeavesTheRayUntouched) {
    // Glass to air (eta 1.5) at 60 degrees: beyond the critical angle asin(1/1.5) = 41.8 degrees.
    const Ray in{{0, -std::sin(M_PI / 3), std::cos(M_PI / 3)}, {0, std::sin(M_PI / 3), -std::cos(M_PI / 3)}};
    const Step s = step(in, 0, 10, 1.5);
    EXPECT_EQ(s.why, BlockReason::TotalInternalReflection);
    EXPECT_EQ(s.ray.origin.y, in.origin.y);
    EXPECT_EQ(s.ray.direction.z, in.direction.z);
    // Exactly at the critical angle the ray either leaves grazing or reflects: never NaN.
    const double c = std::asin(1 / 1.5);
    const Step crit = step({{0, -std::sin(c), std::cos(c)}, {0, std::sin(c), -std::cos(c)}}, 0, 10, 1.5);
    expectFiniteUnit(crit.ray);
    if (crit.why == BlockReason::None) EXPECT_NEAR(crit.ray.direction.z, 0, 1e-7);
    else EXPECT_EQ(crit.why, BlockReason::TotalInternalReflection);

    // In a lens: a flat front, then R = 4 (glass to air). A parallel ray at 3.9 mm meets the back at
    // asin(3.9 / 4) = 77 degrees.
    const LensSystem lens = builtTable("0 0 1.5 8\n4 5 1 8\n0 1 0 4\n");
    const TraceResult r = traceRay(lens, {{0, 3.9, 1}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    EXPECT_EQ(r.blocked, BlockReason::TotalInternalReflection);
    EXPECT_EQ(r.surface, 1);
    EXPECT_STREQ(blockReasonName(r.blocked), "total internal reflection");
    expectFiniteUnit(r.ray);
}

// ---- radii ------------------------------------------------------------------------------------

TEST(Extremes, MicrometreRadiusRefusesADiameterLargerThanItsSphere) {
    try {
        builtTable("0 0 0 0.001\n0.001 0.0005 1.5 0.003\n-0.001 0.002 0 0.002\n");
        FAIL() << "a 3 um diameter on a 1 um radius was accepted";
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.problem(), "diameter 0.003 mm is larger than the sphere of radius 0.001 mm allows (at most 0.002 mm)");
    }
}

TEST(Extremes, MicrometreBallLensWithTheStopFirstIsAnalysed) {
    // A ball lens of radius 1e-3 mm (full hemispheres, touching at the rim) behind a 1 um stop.
    const LensSystem lens = builtTable("0 0 0 0.001\n0.001 0.0005 1.5 0.002\n-0.001 0.002 0 0.002\n");
    const LensAnalysis a = analyzeLens(lens, std::nullopt, kInf);
    expectAllFinite(a);
    const double n = 1.5, d = 0.002;
    EXPECT_NEAR(a.firstOrder.efl, n * d / (4 * (n - 1)), 1e-12);  // ball lens: f = n D / (4 (n - 1))
    EXPECT_NEAR(a.firstOrder.zPPrime, -0.0015, 1e-12);             // both principal planes at the centre
    EXPECT_NEAR(a.pupils.entrance.z, 0, 1e-15);                    // the stop itself, nothing in front
    EXPECT_NEAR(a.pupils.entrance.magnification, 1, 1e-12);
    EXPECT_NEAR(a.stopDiameter, 0.001, 1e-12);
    // Strong undercorrected spherical aberration at f/1.5: the best focus lies in front of F'.
    EXPECT_GT(a.focus.imageZExact, a.firstOrder.zFPrime);
    EXPECT_LT(a.focus.imageZExact, lens.rearZ());
}

TEST(Extremes, GigametreRadiiGiveAFiniteWeakLens) {
    // Biconvex with R = 1e9 mm: f ~ R / (2 (n - 1)) = 1e9 mm, still exactly computed.
    const LensSystem lens = builtTable("1e9 0 1.5 20\n-1e9 5 1 20\n0 5 0 10\n");
    const FirstOrder fo = computeFirstOrder(lens);
    const double n = 1.5, R = 1e9, t = 5;
    const double power = (n - 1) * (2 / R) - (n - 1) * (n - 1) * t / (n * R * R);
    EXPECT_NEAR(fo.efl, 1 / power, 1e-6 * (1 / power));
    expectOpticsError([&] { focusAt(lens, fo, computePupils(lens), 1e5); }, "inside the front focal length");
    const LensAnalysis a = analyzeLens(lens, std::nullopt, kInf);
    expectAllFinite(a);
    EXPECT_NEAR(a.focus.imageZExact, fo.zFPrime, 1e-3 * fo.efl);
}

TEST(Extremes, FlatSurfacesRefractAndAWindowIsAfocal) {
    // Plano-convex, flat side first: f = R / (n - 1) whatever the thickness.
    const FirstOrder fo = computeFirstOrder(builtTable("0 0 1.5 20\n-50 5 1 20\n0 2 0 10\n"));
    EXPECT_NEAR(fo.efl, 100, 1e-9);
    EXPECT_NEAR(fo.zPPrime, -5, 1e-9);  // on the curved vertex
    expectOpticsError([] { computeFirstOrder(builtTable("0 0 1.5 20\n0 5 1 20\n0 2 0 10\n")); }, "afocal");
}

// ---- stops and f-numbers ----------------------------------------------------------------------

TEST(Extremes, OneMicrometreStopIsAnalysedAtItsOwnFNumber) {
    // Slower than kNarrowestFstop: the widest the lens allows is still a valid setting.
    const LensAnalysis a = analyzeLens(dgaussWithStopRow(0.001), std::nullopt, kInf);
    expectAllFinite(a);
    EXPECT_NEAR(a.stopDiameter, 0.001, 1e-9);
    EXPECT_GT(a.fstop, kNarrowestFstop);
    EXPECT_NEAR(a.fstop, a.firstOrder.efl / a.pupils.entrance.diameter, 1e-3 * a.fstop);
    EXPECT_DOUBLE_EQ(a.aperture.fstopMax, a.aperture.fstopMin);
    expectOpticsError([&] { analyzeLens(dgaussWithStopRow(0.001), 16.0, kInf); }, "outside this lens's range f/");
}

TEST(Extremes, FullyOpenStopIsLimitedByTheElements) {
    // dgauss's elements already clip the f/2 cone before its 17.1 mm stop: opening it changes nothing.
    const LensAnalysis asTable = analyzeLens(dgauss(), std::nullopt, kInf);
    const LensAnalysis open = analyzeLens(dgaussWithStopRow(1000), std::nullopt, kInf);
    expectAllFinite(open);
    EXPECT_NEAR(open.fstop, asTable.fstop, 1e-9);
    EXPECT_NEAR(open.stopDiameter, asTable.stopDiameter, 1e-9);
    EXPECT_LT(open.stopDiameter, 17.1);
    // A singlet with the stop behind it: opened from 10 mm to 1 m, the 20 mm lens is the limit.
    const LensAnalysis small = analyzeLens(builtTable("50 0 1.5 20\n-50 5 1 20\n0 5 0 10\n"), std::nullopt, kInf);
    const LensAnalysis wide = analyzeLens(builtTable("50 0 1.5 20\n-50 5 1 20\n0 5 0 1000\n"), std::nullopt, kInf);
    expectAllFinite(wide);
    EXPECT_NEAR(small.stopDiameter, 10, 1e-6);
    EXPECT_LT(wide.fstop, small.fstop);
    EXPECT_GT(wide.stopDiameter, 10);
    EXPECT_LT(wide.stopDiameter, 20);
}

TEST(Extremes, FNumbersAtAndJustBeyondTheLimits) {
    const LensSystem lens = dgauss();
    const FirstOrder fo = computeFirstOrder(lens);
    const ApertureRange range = computeApertureRange(lens, fo);
    EXPECT_NEAR(stopDiameterForFstop(lens, fo, range, range.fstopMin), range.stopDiameterMax, 1e-9);
    EXPECT_NO_THROW(stopDiameterForFstop(lens, fo, range, range.fstopMin * (1 - 1e-12)));
    const double tiny = stopDiameterForFstop(lens, fo, range, kNarrowestFstop);
    EXPECT_GT(tiny, 0);
    // Nearly paraxial there: the opening halves when the f-number doubles (to 2e-5: spherical aberration).
    EXPECT_NEAR(tiny, 0.5 * stopDiameterForFstop(lens, fo, range, 0.5 * kNarrowestFstop), 1e-4 * tiny);
    for (double bad : {range.fstopMin * 0.999, kNarrowestFstop * 1.0001, 0.0, -2.0, kInf, kNaN})
        expectOpticsError([&] { stopDiameterForFstop(lens, fo, range, bad); }, "outside this lens's range f/");
    expectOpticsError([&] { stopDiameterForFstop(lens, fo, range, kNarrowestFstop * 1.0001); }, "to f/64");
}

TEST(Extremes, FineStopListsRefuseEndlessRequests) {
    EXPECT_EQ(fineStops(2.0198, 2.5).size(), 5u);  // 2.1 ... 2.5
    EXPECT_EQ(fineStops(35000, 35000).size(), 1u);  // a lens slower than kNarrowestFstop: its one setting
    for (double step : {0.0, -0.1, kNaN})
        expectOpticsError([&] { fineStops(2, 16, step); }, "not a finite list");
    expectOpticsError([] { fineStops(2, 1e8); }, "not a finite list of at most 100000");
    expectOpticsError([] { fineStops(2, kInf); }, "not a finite list");
    expectOpticsError([] { fineStops(1e300, 1e300); }, "not a finite list");
}

// ---- focus ------------------------------------------------------------------------------------

TEST(Extremes, FocusFromInfinityToTheClosestAndJustInside) {
    const LensSystem lens = dgauss();
    const FirstOrder fo = computeFirstOrder(lens);
    const Pupils pupils = computePupils(lens);
    const FocusResult far = focusAt(lens, fo, pupils, kInf);
    EXPECT_TRUE(far.infinity);
    EXPECT_EQ(far.imageZThick, fo.zFPrime);
    EXPECT_NEAR(far.imageZExact, fo.zFPrime, 0.2);  // spherical aberration of the f/2 cone

    const double closest = closestFocusDistance(fo) - lens.frontZ();
    const FocusResult near = focusAt(lens, fo, pupils, closest);
    EXPECT_NEAR(near.imageZThick, fo.zPPrime - 11 * fo.efl, 1e-9 * fo.efl);  // magnification 10
    EXPECT_TRUE(std::isfinite(near.imageZExact));
    EXPECT_GT(near.raysUsed, 0);

    expectOpticsError([&] { focusAt(lens, fo, pupils, closest * (1 - 1e-9)); }, "closer than this lens can focus");
    const double ffd = fo.zF - lens.frontZ();
    expectOpticsError([&] { focusAt(lens, fo, pupils, ffd); }, "inside the front focal length");
    expectOpticsError([&] { focusAt(lens, fo, pupils, std::nextafter(ffd, 0.0)); }, "inside the front focal length");
    for (double bad : {0.0, -1.0, kNaN})
        expectOpticsError([&] { focusAt(lens, fo, pupils, bad); }, "focus distance must be positive");
}

// ---- stop position ----------------------------------------------------------------------------

TEST(Extremes, StopFirstOrLastMakesThatPupilTheStopItself) {
    const LensAnalysis first = analyzeLens(builtTable("0 0 0 10\n50 5 1.5 20\n-50 5 0 20\n"), std::nullopt, 1000);
    expectAllFinite(first);
    EXPECT_NEAR(first.pupils.entrance.z, 0, 1e-12);
    EXPECT_NEAR(first.pupils.entrance.diameter, first.stopDiameter, 1e-12);

    const LensAnalysis last = analyzeLens(builtTable("50 0 1.5 20\n-50 5 1 20\n0 5 0 10\n"), std::nullopt, 1000);
    expectAllFinite(last);
    EXPECT_NEAR(last.pupils.exit.z, -10, 1e-12);
    EXPECT_NEAR(last.pupils.exit.diameter, last.stopDiameter, 1e-12);
    // The thick lens passes the axial ray and clips just outside the exit pupil (the stop).
    const double r = 0.5 * last.pupils.exit.diameter;
    EXPECT_TRUE(traceThick(last.thick, {{0, 0, -20}, {0, 0, 1}}, TraceDirection::FilmToScene).ok());
    EXPECT_EQ(traceThick(last.thick, {{0, r * 1.001, -20}, {0, 0, 1}}, TraceDirection::FilmToScene).blocked,
              BlockReason::ClippedByStop);
}
