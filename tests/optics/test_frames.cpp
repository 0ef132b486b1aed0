// Tilts, decentres and folds: coordinate breaks that undo each other leave every ray as it was, a
// fold mirror leaves first-order data as the unfolded system has them, a tilted plate shifts a ray
// by the closed form, and the batch trace through moved surfaces equals the scalar one to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "firstorder/Aperture.h"
#include "firstorder/Chromatic.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Pupils.h"
#include "analysis/PupilAiming.h"
#include "analysis/SpotDiagram.h"
#include "prescription/CodeVFile.h"
#include "prescription/FrameChange.h"
#include "prescription/LensSystem.h"
#include "trace/AxisRay.h"
#include "trace/ExactTrace.h"
#include "trace/RayBatch.h"
#include "PrescriptionRows.h"
#include "prescription/Pi.h"

using namespace lenslab;

namespace {

LensTableRow row(double radius, double gap, double index, double diameter, int line) {
    LensTableRow r = test::row(radius, gap, index, diameter);
    r.line = line;
    return r;
}

LensTableRow coordinateBreak(std::array<double, 3> decentre, std::array<double, 3> tilt, TiltOrder order, int line) {
    LensTableRow r;
    r.coordinateBreak = true;
    r.frame = FrameChange{decentre, tilt, FrameMode::Basic, order};
    r.line = line;
    return r;
}

// A gap-after singlet focusing at about 50 mm, the stop on its front.
LensTable gapAfterSinglet() {
    LensTable t;
    t.name = "singlet";
    t.layout = TableLayout::GapAfter;
    t.format = "zmx";
    t.rows = {row(40, 5, 1.6, 20, 1), row(-60, 30, 0, 20, 2), row(0, 20, 0, 30, 3)};
    t.rows[0].stop = true;
    return t;
}

std::vector<Ray> testRays() {
    std::vector<Ray> rays;
    for (double y : {-6.0, -2.0, 0.0, 3.0, 7.0})
        for (double slope : {-0.05, 0.0, 0.08}) rays.push_back({{0.7 * slope * 10, y, 10}, normalize({0.01, slope, -1})});
    return rays;
}

void expectSameRay(const Ray& a, const Ray& b, double tolerance) {
    EXPECT_NEAR(a.origin.x, b.origin.x, tolerance);
    EXPECT_NEAR(a.origin.y, b.origin.y, tolerance);
    EXPECT_NEAR(a.origin.z, b.origin.z, tolerance);
    EXPECT_NEAR(a.direction.x, b.direction.x, tolerance);
    EXPECT_NEAR(a.direction.y, b.direction.y, tolerance);
    EXPECT_NEAR(a.direction.z, b.direction.z, tolerance);
}

// The ray's line where it crosses the plane at lens z.
Ray onPlane(const Ray& r, double z) {
    const double t = (z - r.origin.z) / r.direction.z;
    return {{r.origin.x + t * r.direction.x, r.origin.y + t * r.direction.y, z}, r.direction};
}

}  // namespace

// Zemax undoes a coordinate break with one of the opposite values and the other order flag.
TEST(Frames, DecentredThenRecentredCoordinateBreaksAreTheIdentity) {
    const FrameChange there{{1.3, -0.7, 0}, {5, -3, 20}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    const FrameChange back{{-1.3, 0.7, 0}, {-5, 3, -20}, FrameMode::Basic, TiltOrder::TiltThenDecentre};
    const RigidMotion both = surfaceMotions(there, -7.5).before.then(surfaceMotions(back, -7.5).before);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(both.rotation[i], i % 4 == 0 ? 1 : 0, 1e-15);
    for (double s : both.shift) EXPECT_NEAR(s, 0, 1e-14);

    const LensTable plain = gapAfterSinglet();
    LensTable broken = plain;
    broken.rows.insert(broken.rows.begin() + 1, {coordinateBreak(there.decentre, there.tiltDegrees, there.order, 10),
                                                 coordinateBreak(back.decentre, back.tiltDegrees, back.order, 11)});
    const LensSystem a = buildLensSystem(plain), b = buildLensSystem(broken);
    ASSERT_EQ(b.surfaces.size(), a.surfaces.size());  // a coordinate break is no surface
    EXPECT_TRUE(b.hasMovedSurfaces());
    for (const Ray& ray : testRays()) {
        const TraceResult ra = traceRay(a, ray, TraceDirection::SceneToFilm);
        const TraceResult rb = traceRay(b, ray, TraceDirection::SceneToFilm);
        ASSERT_EQ(ra.blocked, rb.blocked);
        expectSameRay(ra.ray, rb.ray, 1e-12);
    }
}

// Code V's DAR moves one surface only: a tilted, decentred flat between equal media changes no ray.
TEST(Frames, DecentreAndReturnMovesOnlyItsSurface) {
    const std::string text = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ns -60 10\ns 0 20\nyde 3; ade 12; xde -1; dar\n"
                             "s 0 20\nepd 10; wl 587.56\n";
    const std::string plainText = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ns -60 10\ns 0 20\ns 0 20\nepd 10; wl 587.56\n";
    const LensSystem moved = buildLensSystem(parseCodeV(text, "dar.seq"));
    const LensSystem plain = buildLensSystem(parseCodeV(plainText, "plain.seq"));
    for (const Ray& ray : testRays()) {
        const TraceResult rm = traceRay(moved, ray, TraceDirection::SceneToFilm);
        const TraceResult rp = traceRay(plain, ray, TraceDirection::SceneToFilm);
        ASSERT_EQ(rm.ok(), rp.ok());
        // A decentred lens's flats between equal media move coordinates, not rays: its ray ends at the
        // last real surface. Both lines then cross the last flat's plane (z = -35) at one point.
        expectSameRay(onPlane(rm.ray, -35), onPlane(rp.ray, -35), 1e-12);
    }
}

// A flat mirror at 45 degrees (Code V ADE 45 with BEN) between a singlet and its image: the first-
// order data are the unfolded singlet's, to rounding.
TEST(Frames, FoldMirrorAt45DegreesLeavesFirstOrderAsUnfolded) {
    const std::string unfolded = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ns -60 30\ns 0 40\nsi 0 0\nepd 10; wl 587.56\n";
    const std::string folded = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ns -60 30\ns 0 -40 refl\nade 45; ben\nsi 0 0\n"
                               "epd 10; wl 587.56\n";
    const LensSystem u = buildLensSystem(parseCodeV(unfolded, "u.seq"));
    const LensSystem f = buildLensSystem(parseCodeV(folded, "f.seq"));
    const FirstOrder a = computeFirstOrder(u), b = computeFirstOrder(f);
    EXPECT_NEAR(b.efl, a.efl, 1e-9 * a.efl);
    EXPECT_NEAR(b.zFPrime, a.zFPrime, 1e-9 * a.efl);
    EXPECT_NEAR(b.zPPrime, a.zPPrime, 1e-9 * a.efl);
    EXPECT_NEAR(b.zF, a.zF, 1e-9 * a.efl);
    EXPECT_NEAR(b.zP, a.zP, 1e-9 * a.efl);
    // The real layout: the axis turns by 90 degrees at the mirror, 35 mm behind the front vertex.
    std::vector<Vec3> path;
    TraceOptions options;
    options.path = &path;
    const TraceResult r = traceRay(f, {{0, 0, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm, options);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(path.size(), 4u);
    EXPECT_NEAR(path[3].z, -35, 1e-12);
    EXPECT_NEAR(path[3].y, 0, 1e-12);
    // In image space the ray runs along the axis toward the film, as through the unfolded lens.
    EXPECT_NEAR(r.ray.direction.z, -1, 1e-15);
}

// Code V's alpha (ADE) and beta (BDE) turn the same way about their axes, so a lens tilted by BDE
// and decentred along x is the one tilted by ADE and decentred along y, turned 90 degrees about the
// axis (x -> y, y -> -x): each ray turned likewise comes out turned likewise. A beta traced with the
// opposite sign breaks it by millimetres.
TEST(Frames, BetaTiltIsAlphaTiltTurnedAQuarterAboutTheAxis) {
    const std::string alpha = "rdm\nso 0 1e10\ns 40 5 1.6,40\nyde 1.5; ade 6\nsto\ns -60 30\ns 0 20\nepd 10; wl 587.56\n";
    const std::string beta = "rdm\nso 0 1e10\ns 40 5 1.6,40\nxde -1.5; bde 6\nsto\ns -60 30\ns 0 20\nepd 10; wl 587.56\n";
    const LensSystem a = buildLensSystem(parseCodeV(alpha, "alpha.seq"));
    const LensSystem b = buildLensSystem(parseCodeV(beta, "beta.seq"));
    const LensSystem plain = buildLensSystem(
        parseCodeV("rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ns -60 30\ns 0 20\nepd 10; wl 587.56\n", "plain.seq"));
    const auto turned = [](const Ray& r) {
        return Ray{{-r.origin.y, r.origin.x, r.origin.z}, {-r.direction.y, r.direction.x, r.direction.z}};
    };
    double largestShift = 0;
    int passed = 0;
    for (const Ray& ray : testRays()) {
        const TraceResult ra = traceRay(a, ray, TraceDirection::SceneToFilm);
        const TraceResult rb = traceRay(b, turned(ray), TraceDirection::SceneToFilm);
        ASSERT_EQ(ra.ok(), rb.ok());  // the stop (EPD 10) passes the same rays, turned
        if (!ra.ok()) continue;
        ++passed;
        expectSameRay(onPlane(rb.ray, -35), turned(onPlane(ra.ray, -35)), 1e-12);
        const Ray tilted = onPlane(ra.ray, -35), straight = onPlane(traceRay(plain, ray, TraceDirection::SceneToFilm).ray, -35);
        largestShift = std::max(largestShift, std::hypot(tilted.origin.x - straight.origin.x, tilted.origin.y - straight.origin.y));
    }
    // The tilt and decentre move the rays by millimetres: the check above is not a trivial one.
    EXPECT_GE(passed, 6);
    EXPECT_GT(largestShift, 1.0);
}

// A plate of thickness t and index n tilted by theta shifts a ray across by t sin(theta - theta') /
// cos theta', sin theta' = sin theta / n, and leaves it parallel.
TEST(Frames, TiltedPlateShiftsARayByTheClosedForm) {
    const double t = 8, theta = 25;
    const std::string text = "rdm\nso 0 1e10\ns 0 20\nsto\ns 0 8 1.7,50\nade 25\ns 0 30\nade 25; rev\nepd 10; wl 587.56\n";
    const LensSystem lens = buildLensSystem(parseCodeV(text, "plate.seq"));
    // The model glass at 587.56 nm, a little off the d line its 1.7 is stated at.
    const double n = lens.surfaces[1].indexAfter;
    ASSERT_NEAR(n, 1.7, 1e-6);
    const double th = theta * kPi / 180, thPrime = std::asin(std::sin(th) / n);
    const double expected = t * std::sin(th - thPrime) / std::cos(thPrime);
    // The ray's line before and after, in object-space coordinates.
    RigidMotion toImage;
    for (const Surface& s : lens.surfaces) toImage = toImage.then(s.before).then(s.after);
    const RigidMotion toObject = toImage.inverse();
    for (double y : {-2.0, 0.0, 3.0}) {
        const Ray in{{0, y, 10}, {0, 0, -1}};
        const TraceResult r = traceRay(lens, in, TraceDirection::SceneToFilm);
        ASSERT_TRUE(r.ok());
        // REV turns the axis back after the plate: in image-space coordinates the ray leaves along z.
        EXPECT_NEAR(r.ray.direction.y, 0, 1e-14);
        EXPECT_NEAR(r.ray.direction.z, -1, 1e-14);
        const auto p = toObject.applyToPoint({r.ray.origin.x, r.ray.origin.y, r.ray.origin.z});
        const auto d = toObject.applyToDirection({r.ray.direction.x, r.ray.direction.y, r.ray.direction.z});
        EXPECT_NEAR(d[0], 0, 1e-14);
        EXPECT_NEAR(d[1], 0, 1e-14);
        EXPECT_NEAR(d[2], -1, 1e-14);
        EXPECT_NEAR(std::fabs(p[1] - y), expected, 1e-12);
        EXPECT_NEAR(p[0], 0, 1e-14);
    }
}

// A tilted plate of N-BK7 before an N-BK7 singlet adds no power: the focal lengths at F, d and C are
// the singlet's, from the thick-lens formula with Schott's Sellmeier indices written out here. The
// plate moves the axis ray differently at each wavelength; measured about the primary wavelength's
// axis, the F and C focal lengths came out 4.7 and 0.6 mm.
TEST(Frames, TiltedPlateLeavesTheFocalLengthAtEveryWavelength) {
    const std::string text = "rdm\nso 0 1e10\ns 0 4 n-bk7_schott\ndar\nade 10\ns 0 5\ndar\nade 10\n"
                             "s 50 5 n-bk7_schott\nsto\ns -50 45\nsi 0 0\nepd 10; wl 587.5618\n";
    const LensSystem lens = buildLensSystem(parseCodeV(text, "plate.seq"));
    auto bk7 = [](double nm) {
        const double l2 = nm * nm * 1e-6;
        return std::sqrt(1 + 1.03961212 * l2 / (l2 - 0.00600069867) + 0.231792344 * l2 / (l2 - 0.0200179144) +
                         1.01046945 * l2 / (l2 - 103.560653));
    };
    auto singletEfl = [&](double nm) {
        const double n = bk7(nm);
        return 1 / ((n - 1) * (2 / 50.0 - (n - 1) * 5 / (n * 50 * 50)));
    };
    const Chromatic c = computeChromatic(alongAxisRay(lens), std::numeric_limits<double>::infinity(), std::nullopt);
    EXPECT_NEAR(c.eflF, singletEfl(kWavelengthF), 1e-9);
    EXPECT_NEAR(c.eflD, singletEfl(kWavelengthD), 1e-9);
    EXPECT_NEAR(c.eflC, singletEfl(kWavelengthC), 1e-9);
    EXPECT_NEAR(c.eflF, 48.69, 0.01);  // about 49.21 x (nd - 1) / (nF - 1)
}

// The batch trace takes the same steps as the scalar one through frames, shapes and forms.
TEST(Frames, BatchEqualsScalarThroughMovedShapedSurfaces) {
    const std::string text = "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ncir 9\ns -60 10\nyde 0.4; ade 2; dar\n"
                             "rex 8; rey 6; ady 0.5\ns 0 -20 refl\nade 30; ben\ns 0 -5\ncir obs 1; ady 0.3\nepd 10; wl 587.56\n";
    const LensSystem lens = buildLensSystem(parseCodeV(text, "b.seq"));
    const std::vector<Ray> rays = testRays();
    RayBatch batch;
    batch.resize(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) batch.set(i, rays[i]);
    traceBatch(lens, batch, TraceDirection::SceneToFilm);
    int passed = 0, blocked = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const TraceResult r = traceRay(lens, rays[i], TraceDirection::SceneToFilm);
        ASSERT_EQ(batch.blocked[i], r.blocked) << i;
        if (!r.ok()) {
            ++blocked;
            continue;
        }
        ++passed;
        const Ray b = batch.get(i);
        EXPECT_EQ(b.origin.x, r.ray.origin.x);
        EXPECT_EQ(b.origin.y, r.ray.origin.y);
        EXPECT_EQ(b.origin.z, r.ray.origin.z);
        EXPECT_EQ(b.direction.y, r.ray.direction.y);
        EXPECT_EQ(b.direction.z, r.ray.direction.z);
    }
    EXPECT_GT(passed, 3);
    EXPECT_GT(blocked, 0);  // the rectangle and the decentred obscuration stop some
}

// An off-axis paraboloid (a decentred section, the stop on the beam): the axis ray through the
// stop's centre meets the mirror 50 mm off the parent axis and is turned onto z.
TEST(Frames, OffAxisParaboloidIsMeasuredAlongItsAxisRay) {
    const std::string text = "rdm\nso 0 1e10\ns 0 100\nsto\ncir 5\ns -200 -100 refl\ncon; k -1\nyde -50\nsi 0 0\n"
                             "epd 10; wl 550\n";
    const LensSystem lens = buildLensSystem(parseCodeV(text, "oap.seq"));
    const auto axis = axisRay(lens);
    ASSERT_TRUE(axis);
    EXPECT_NEAR(axis->origin.y, 0, 1e-12);
    const LensSystem aligned = alongAxisRay(lens);
    const TraceResult r = traceRay(aligned, *axis, TraceDirection::SceneToFilm);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r.ray.direction.x, 0, 1e-12);
    EXPECT_NEAR(r.ray.direction.y, 0, 1e-12);
    EXPECT_NEAR(r.ray.direction.z, -1, 1e-12);
    EXPECT_NEAR(r.ray.origin.y, 0, 1e-9);
    // A paraboloid focuses a beam parallel to its axis at its focus, f + h^2 / (4 f) from the zone
    // at height h: the focal length along the axis ray, and where the back focal point lies on it.
    const double f = 100, h = 50, toFocus = f + h * h / (4 * f);
    const FirstOrder fo = computeFirstOrder(aligned);
    EXPECT_NEAR(fo.efl, toFocus, 1e-6 * toFocus);
    EXPECT_NEAR(fo.zFPrime, r.ray.origin.z - toFocus, 1e-6 * toFocus);
}

// A decentred lens's vertices lie off its axis: its focal distances run from where the axis meets
// its outermost surfaces that bend light, not from the dummy surfaces that only place what follows
// (HoO-V2C18Ex46's back focal distance read 210.93 mm from a coordinate break, 208.15 mm along its
// axis ray). Decentred dummies before and after a singlet leave the thick-lens formula's distances.
TEST(Frames, FocalDistancesRunFromTheSurfacesOnTheAxisNotFromDummies) {
    const double r1 = 40, r2 = -60, t = 5, n = 1.6;
    const std::string singlet = "s 40 5 1.6,40\nsto\ns -60 30\n";
    const LensSystem plain = buildLensSystem(parseCodeV("rdm\nso 0 1e10\n" + singlet + "si 0 0\nepd 10; wl 587.5618\n", "p.seq"));
    const LensSystem dummies = buildLensSystem(
        parseCodeV("rdm\nso 0 1e10\ns 0 12\nyde 2\n" + singlet + "s 0 10\nyde 3\nsi 0 0\nepd 10; wl 587.5618\n", "d.seq"));
    ASSERT_TRUE(dummies.decentred);
    const double f = 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
    const FirstOrder a = computeFirstOrder(plain), b = computeFirstOrder(alongAxisRay(dummies));
    EXPECT_NEAR(a.backFocalDistance, f * (1 - (n - 1) * t / (n * r1)), 1e-9 * f);
    EXPECT_NEAR(a.frontFocalDistance, f * (1 + (n - 1) * t / (n * r2)), 1e-9 * f);
    EXPECT_NEAR(b.efl, a.efl, 1e-9 * f);
    EXPECT_NEAR(b.backFocalDistance, a.backFocalDistance, 1e-9 * f);
    EXPECT_NEAR(b.frontFocalDistance, a.frontFocalDistance, 1e-9 * f);
}

// A decentred, tilted stop (Code V DAR: only the stop moves) between two singlets: its opening is
// measured from its own centre in its own plane, and its images (the pupils) from rays that leave
// that centre along the axis ray. threemir.seq's entrance pupil read 203.1 mm for rays spanning
// 102.5 mm, and --fstop 8 left its stop as wide as f/4's, because both came from the axis of the
// coordinates arriving at the stop, 11.4 mm from its centre.
TEST(Frames, DecentredStopIsMeasuredFromItsOwnCentre) {
    const LensSystem lens = alongAxisRay(buildLensSystem(parseCodeV(
        "rdm\nso 0 1e10\ns 100 5 1.6,40\ns -200 10\ns 0 5\nsto\nyde 2; ade 10\ndar\ns 80 5 1.6,40\ns -150 40\nsi 0 0\n"
        "epd 20; wl 587.5618\n",
        "stop.seq")));
    ASSERT_TRUE(lens.decentred);
    const FirstOrder fo = computeFirstOrder(lens);
    const ApertureRange range = computeApertureRange(lens, fo);
    for (const double fstop : {8.0, 16.0}) {
        // The stop opened for an f-number gives that f-number back as its own widest.
        const LensSystem stopped = withStopDiameter(lens, stopDiameterForFstop(lens, fo, range, fstop));
        EXPECT_NEAR(computeApertureRange(stopped, fo).fstopMin, fstop, 1e-6 * fstop);
        // The marginal ray from F' leaves for the scene at the entrance pupil's height, within 1%: the
        // stop is tilted, so its image is too (0.34% seen at f/16).
        const double sinTheta = 1 / (2 * fstop);
        const TraceResult out = traceRay(stopped, {{0, 0, fo.zFPrime}, {0, sinTheta, std::sqrt(1 - sinTheta * sinTheta)}},
                                         TraceDirection::FilmToScene);
        ASSERT_TRUE(out.ok());
        const double entranceHeight = std::fabs(out.ray.origin.y + (0 - out.ray.origin.z) / out.ray.direction.z * out.ray.direction.y);
        EXPECT_NEAR(computePupils(stopped).entrance.diameter, 2 * entranceHeight, 1e-2 * 2 * entranceHeight)
            << "f/" << fstop;
        // The spot's rays are aimed at points of the stop itself: on axis, with the stop the only
        // aperture, every one passes (threemir.seq's on-axis spot read a transmission of 0.691,
        // aimed at a disc 11.4 mm off its stop; its RMS now equals ray-optics' to 1e-5).
        const std::optional<FieldAim> aim = aimField(stopped, ObjectField{});
        ASSERT_TRUE(aim.has_value());
        const ImageRays rays = settledImageRays(stopped, *aim, fo.zFPrime, PupilQuadrature{}, 0.005, 64);
        EXPECT_NEAR(rays.arrivingWeight(), 1.0, 1e-9) << "f/" << fstop;
    }
}
