// Mirrors in the sequential trace: the law of reflection, a classical Cassegrain (parabolic primary,
// hyperbolic secondary) imaging an axial point perfectly at the focal length its textbook formulas
// give, the central obscuration, and the checks on a prescription's mirrors.
#include <gtest/gtest.h>

#include <cmath>

#include "trace/ExactTrace.h"
#include "firstorder/Aperture.h"
#include "firstorder/FirstOrder.h"
#include "settings/LensAnalysis.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

// Primary: concave paraboloid, R1 = -200 (focal length f1 = 100, focus 100 mm toward the scene).
// Secondary 80 mm in front of it intercepts the cone 20 mm before the primary's focus; magnification
// m = 5 puts the image s' = m s = 100 mm behind the secondary, i.e. 20 mm behind the primary. Mirror
// equation: 1/s' - 1/s = -2/R2 gives |R2| = 2 s s' / (s' - s) = 50 (convex); the secondary conic for
// a perfect axial image is -((m + 1)/(m - 1))^2 = -2.25; system focal length m f1 = 500.
constexpr double kF1 = 100, kGap = 80, kM = 5;

LensTable cassegrainTable(double secondaryConic, double obscuration) {
    LensTable t;
    t.name = "cassegrain";
    t.layout = TableLayout::GapAfter;
    t.format = "zmx";
    LensTableRow primary;
    primary.radius = -2 * kF1;
    primary.conic = -1;
    primary.gap = -kGap;  // back toward the scene after the mirror
    primary.diameter = 100;
    primary.mirror = true;
    primary.stop = true;
    primary.obscurationDiameter = obscuration;
    primary.line = 1;
    LensTableRow secondary;
    const double s = kF1 - kGap, sPrime = kM * s;
    secondary.radius = -2 * s * sPrime / (sPrime - s);
    secondary.conic = secondaryConic;
    secondary.diameter = 24;
    secondary.mirror = true;
    secondary.line = 2;
    t.rows = {primary, secondary};
    return t;
}

double rmsAxialSpot(const LensSystem& lens, double z, double radius, int* obscured = nullptr) {
    double sum = 0;
    int count = 0;
    for (int i = -16; i <= 16; ++i)
        for (int j = -16; j <= 16; ++j) {
            const double x = radius * i / 16, y = radius * j / 16;
            if (x * x + y * y > radius * radius) continue;
            const TraceResult r = traceRay(lens, {{x, y, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
            if (r.blocked == BlockReason::Obscured && obscured) ++*obscured;
            if (!r.ok()) continue;
            const Vec3 p = pointAt(r.ray, (z - r.ray.origin.z) / r.ray.direction.z);
            sum += p.x * p.x + p.y * p.y;
            ++count;
        }
    return count ? std::sqrt(sum / count) : NAN;
}

}  // namespace

TEST(Mirrors, ReflectionObeysTheLawOfReflection) {
    const LensSystem lens = buildLensSystem(cassegrainTable(-2.25, 0));
    const Ray in{{3, 30, 10}, normalize(Vec3{0.01, -0.02, -1})};
    std::vector<Vec3> path;
    TraceOptions o;
    o.end = 1;
    o.path = &path;
    const TraceResult r = traceRay(lens, in, TraceDirection::SceneToFilm, o);
    ASSERT_TRUE(r.ok());
    const Vec3 hit = path[1];
    // Paraboloid z = -(x^2 + y^2) / (2 R) about the vertex (R = -200): the normal from the gradient.
    const Vec3 normal = normalize(Vec3{-hit.x / 200, -hit.y / 200, 1});
    EXPECT_NEAR(hit.z, (hit.x * hit.x + hit.y * hit.y) / 400, 1e-12);
    EXPECT_NEAR(dot(in.direction, normal), -dot(r.ray.direction, normal), 1e-14);
    const Vec3 expected = in.direction - 2 * dot(in.direction, normal) * normal;
    EXPECT_NEAR(length(expected - r.ray.direction), 0, 1e-14);
    EXPECT_GT(r.ray.direction.z, 0);  // back toward the scene
}

TEST(Mirrors, ClassicalCassegrainImagesTheAxisPerfectlyAtItsTextbookFocalLength) {
    const LensSystem lens = buildLensSystem(cassegrainTable(-((kM + 1) / (kM - 1)) * ((kM + 1) / (kM - 1)), 0));
    const FirstOrder fo = computeFirstOrder(lens);
    EXPECT_NEAR(fo.efl, kM * kF1, 1e-6);
    // The image 20 mm behind the primary's vertex.
    EXPECT_NEAR(fo.zFPrime, -(kM * (kF1 - kGap) - kGap), 1e-6);
    EXPECT_LT(rmsAxialSpot(lens, fo.zFPrime, 45), 1e-6 * fo.efl);
    // With a spherical secondary the same telescope has spherical aberration.
    const LensSystem spherical = buildLensSystem(cassegrainTable(0, 0));
    EXPECT_GT(rmsAxialSpot(spherical, fo.zFPrime, 45), 1e-3 * fo.efl);
}

TEST(Mirrors, CentralObscurationBlocksTheMiddleOfTheBundle) {
    const LensSystem lens = buildLensSystem(cassegrainTable(-2.25, 30));
    int obscured = 0;
    rmsAxialSpot(lens, -20, 45, &obscured);
    // Points of the 33 x 33 grid (step 45/16) inside radius 15: count them here.
    int inside = 0;
    for (int i = -16; i <= 16; ++i)
        for (int j = -16; j <= 16; ++j) inside += std::hypot(45.0 * i / 16, 45.0 * j / 16) < 15;
    EXPECT_EQ(obscured, inside);
    EXPECT_EQ(std::string(blockReasonName(BlockReason::Obscured)), "central obscuration");
}

TEST(Mirrors, AnalysisOfAReflexLensIsFinite) {
    const LensAnalysis a = analyzeLens(buildLensSystem(cassegrainTable(-2.25, 30)), std::nullopt, 1e9);
    EXPECT_NEAR(a.firstOrder.efl, 500, 1e-5);
    EXPECT_NEAR(a.fstop, 5.0, 0.05);  // 100 mm aperture, f = 500
    EXPECT_TRUE(std::isfinite(a.pupils.exit.z));
    EXPECT_TRUE(std::isfinite(a.focus.imageZExact));
}

TEST(Mirrors, TheNarrowestFstopIsWhereTheStopClosesIntoTheObscurationsShadow) {
    // The primary is the stop and carries the 30 mm obscuration: light passes only while the stop
    // opens wider than it. The classical Cassegrain images the axis perfectly, so the collimated ray
    // at the obscuration's rim (15 mm) crosses F' at the cone angle of that f-number.
    const LensSystem lens = buildLensSystem(cassegrainTable(-2.25, 30));
    TraceOptions unobscured;
    unobscured.ignoreObscurations = true;
    const TraceResult rim = traceRay(lens, {{0, 15, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm, unobscured);
    ASSERT_TRUE(rim.ok());
    const double sinTheta = std::hypot(rim.ray.direction.x, rim.ray.direction.y);
    const LensAnalysis a = analyzeLens(lens, std::nullopt, kInf);
    EXPECT_NEAR(a.aperture.fstopMax, 1 / (2 * sinTheta), 1e-7);
    EXPECT_NEAR(a.aperture.fstopMax, 500.0 / 30, 0.2);  // near N = f / D
    EXPECT_EQ(analyzeLens(buildLensSystem(cassegrainTable(-2.25, 0)), std::nullopt, kInf).aperture.fstopMax,
              kNarrowestFstop);

    // The bundled reflex lens (its secondary mirror's shadow): every f-number of its range passes
    // light on axis, the first past it none.
    const LensSystem reflex = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us4666259-ex1-reflex-500mm.zmx");
    const ApertureRange range = analyzeLens(reflex, std::nullopt, kInf).aperture;
    EXPECT_GT(range.fstopMax, 1.5 * range.fstopMin);  // f/6.70 to f/13.08
    EXPECT_LT(range.fstopMax, 20);
    const auto axialRaysPass = [&](double fstop) {
        LensSystem stopped = reflex;
        const FirstOrder fo = computeFirstOrder(stopped);
        ApertureRange wide = range;
        wide.fstopMax = kNarrowestFstop;
        stopped.surfaces[stopped.stopIndex].apertureRadius = stopDiameterForFstop(stopped, fo, wide, fstop) / 2;
        int passed = 0;
        for (int k = 0; k <= 2000; ++k) {
            const double y = stopped.surfaces[0].apertureRadius * k / 2000;
            passed += traceRay(stopped, {{0, y, 100}, {0, 0, -1}}, TraceDirection::SceneToFilm).ok();
        }
        return passed;
    };
    EXPECT_GT(axialRaysPass(range.fstopMax * 0.98), 0);
    EXPECT_EQ(axialRaysPass(range.fstopMax * 1.05), 0);
}

// One mirror sends the light back toward the scene: the image space is mirrored across the
// mirror's vertex plane so the light leaves toward the film at -z, and the paraboloid's focus (100
// mm in front of it) is its F', 100 mm behind its vertex there. A ray parallel to the axis meets it.
TEST(Mirrors, AnOddNumberOfMirrorsMirrorsTheImageSpace) {
    LensTable t = cassegrainTable(-2.25, 0);
    t.rows.pop_back();
    t.rows[0].gap = -kF1;
    const LensSystem lens = buildLensSystem(t);
    EXPECT_EQ(lens.zDirectionAfter(0), -1);
    const FirstOrder fo = computeFirstOrder(lens);
    EXPECT_NEAR(fo.efl, kF1, 1e-9);
    EXPECT_NEAR(fo.zFPrime, -kF1, 1e-9);
    for (double y : {5.0, 20.0, 45.0}) {
        const TraceResult r = traceRay(lens, {{0, y, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
        ASSERT_TRUE(r.ok());
        EXPECT_LT(r.ray.direction.z, 0);
        const Vec3 p = pointAt(r.ray, (fo.zFPrime - r.ray.origin.z) / r.ray.direction.z);
        EXPECT_NEAR(p.y, 0, 1e-12) << y;  // a paraboloid is perfect on axis
    }
}

TEST(Mirrors, ObscurationAsLargeAsTheApertureIsRefused) {
    try {
        buildLensSystem(cassegrainTable(-2.25, 100));
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 1);
        EXPECT_NE(std::string(e.what()).find("obscuration"), std::string::npos) << e.what();
    }
}

namespace {

// Flat air surfaces 10 mm apart: the first (the stop) tilted about x by tilts[0] degrees (a basic
// decentre: the surfaces after it follow), coordinate breaks by the other tilts after it.
LensTable turnedTable(const std::vector<double>& tilts) {
    LensTable t;
    t.name = "turned";
    t.layout = TableLayout::GapAfter;
    t.format = "zmx";
    LensTableRow flat;
    flat.diameter = 10;
    flat.gap = 10;
    flat.stop = true;
    flat.frame = FrameChange{{}, {tilts[0], 0, 0}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    t.rows.push_back(flat);
    flat.stop = false;
    flat.frame.reset();
    for (std::size_t i = 1; i < tilts.size(); ++i) {
        LensTableRow turn;
        turn.coordinateBreak = true;
        turn.frame = FrameChange{{}, {tilts[i], 0, 0}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
        t.rows.push_back(turn);
    }
    t.rows.push_back(flat);
    t.rows.push_back(flat);
    return t;
}

}  // namespace

// Which way the light runs along z after a surface is decided by the motions together: tilts of 60
// and 45 degrees turn z around as one of 105 does (the axis (0, 0, -1) turned by 105 degrees about x
// has z component -cos 105 > 0). Counting each surface's motion alone said 60 and 45 did not, so a
// Code V fold written as coordinate breaks mirrored its image space the other way.
TEST(Mirrors, MotionsTurnZAroundTogether) {
    ASSERT_GT(-std::cos(105 * M_PI / 180), 0);
    for (const auto& tilts : {std::vector<double>{105}, std::vector<double>{60, 45}, std::vector<double>{35, 35, 35}}) {
        const LensSystem lens = buildLensSystem(turnedTable(tilts));
        ASSERT_EQ(lens.surfaces.size(), 3u);
        EXPECT_EQ(lens.zDirectionAfter(0), tilts[0] > 90 ? 1 : -1) << tilts.size() << " motions";
        EXPECT_EQ(lens.zDirectionAfter(1), 1) << tilts.size() << " motions";
    }
    EXPECT_EQ(buildLensSystem(turnedTable({60})).zDirectionAfter(1), -1);
}
