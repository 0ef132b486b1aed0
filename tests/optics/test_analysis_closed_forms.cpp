// Parts of the designer's analysis that no other test pins with an independent number (issue 32's
// mutation survivors): lateral colour's sign against a chief-ray trace written here at F and C; a
// vignetted spot's RMS over the rays that arrive; the geometric MTF's sagittal and tangential
// directions on a spot that spreads along one; a defocused wavefront's RMS with its piston removed,
// against the closed form; the tangential and sagittal foci against Coddington's equations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "analysis/FieldCurvature.h"
#include "analysis/GeometricMtf.h"
#include "analysis/LensDesignAnalysis.h"
#include "analysis/PupilAiming.h"
#include "analysis/SpotDiagram.h"
#include "analysis/WavefrontMap.h"
#include "firstorder/Chromatic.h"
#include "prescription/Medium.h"
#include "settings/LensAnalysis.h"
#include "PrescriptionRows.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180;

// A ray in the meridional plane: height y, axis position z (lens convention: light runs toward -z).
struct Ray2 {
    double y, z, dy, dz;  // (dy, dz) a unit vector
};

// Snell's law at a surface with unit normal (ny, nz) (either orientation), from index n to n'.
Ray2 refracted(Ray2 r, double ny, double nz, double n, double nPrime) {
    if (r.dy * ny + r.dz * nz > 0) ny = -ny, nz = -nz;  // against the ray
    const double cosI = -(r.dy * ny + r.dz * nz), eta = n / nPrime;
    const double cosT = std::sqrt(1 - eta * eta * (1 - cosI * cosI));
    const double m = eta * cosI - cosT;
    return {r.y, r.z, eta * r.dy + m * ny, eta * r.dz + m * nz};
}

// The ray (running toward -z) at a sphere of vertex z0 and radius R (centre at z0 - R): the
// crossing on the vertex's side, the nearer one when the centre lies ahead (R > 0).
Ray2 toSphere(Ray2 r, double z0, double R, double& ny, double& nz) {
    const double cz = z0 - R, oy = r.y, oz = r.z - cz;
    const double b = oy * r.dy + oz * r.dz, c = oy * oy + oz * oz - R * R;
    const double t = -b - std::copysign(std::sqrt(b * b - c), R);
    r.y += t * r.dy;
    r.z += t * r.dz;
    ny = r.y / R;
    nz = (r.z - cz) / R;
    return r;
}

Ray2 toPlane(Ray2 r, double z) {
    const double t = (z - r.z) / r.dz;
    return {r.y + t * r.dy, z, r.dy, r.dz};
}

// Stop, then a convex face into a model glass, then a flat face: the singlet the tests trace by hand.
struct HandSinglet {
    double stopGap = 15, radius = 60, thickness = 6, nd = 1.5168, vd = 64.17, diameter = 30;
    LensSystem lens() const {
        LensTableRow glass = row(radius, thickness, nd, diameter);
        glass.abbe = vd;
        return buildRows({stopRow(stopGap, 12), glass, row(0, 90, 0, diameter)});
    }
    // The chief ray of a distant field through the stop's centre, traced at index n, at the plane z.
    double chiefHeight(double fieldDegrees, double n, double z) const {
        Ray2 r{0, 0, std::sin(fieldDegrees * kDegree), -std::cos(fieldDegrees * kDegree)};
        double ny, nz;
        r = toSphere(r, -stopGap, radius, ny, nz);
        r = refracted(r, ny, nz, 1, n);
        r = refracted(toPlane(r, -stopGap - thickness), 0, 1, n, 1);
        return toPlane(r, z).y;
    }
};

}  // namespace

// Lateral colour is the F chief ray's height minus the C one's on the d image plane, both at the
// field the analysis names: a positive lens with its stop in front bends blue more, so F - C has
// the sign opposite to the image height.
TEST(Chromatic, LateralColourIsFMinusCByAnIndependentChiefRayTrace) {
    const HandSinglet singlet;
    const LensSystem lens = singlet.lens();
    const double field = 12;
    const Chromatic c = computeChromatic(lens, kInf, field);
    ASSERT_TRUE(c.lateral);
    EXPECT_EQ(c.lateral->fieldDegrees, field);
    const Medium glass = modelGlass(singlet.nd, singlet.vd);
    const auto height = [&](double nm) { return singlet.chiefHeight(field, refractiveIndex(glass, nm), c.imageZD); };
    // The y axis's orientation is the library's: the d chief ray's height fixes it.
    const double sign = height(kWavelengthD) * c.lateral->imageHeight > 0 ? 1 : -1;
    EXPECT_NEAR(sign * height(kWavelengthD), c.lateral->imageHeight, 1e-9);
    const double expected = sign * (height(kWavelengthF) - height(kWavelengthC));
    EXPECT_NEAR(c.lateral->mm, expected, 1e-9);
    EXPECT_GT(std::fabs(expected), 1e-3);
    EXPECT_LT(c.lateral->mm * c.lateral->imageHeight, 0);
}

// A vignetted field: the RMS radius is over the light that reaches the image plane (each ray weighed
// by its share of the stop), not over the whole stop's area.
TEST(SpotDiagram, RmsIsOverTheRaysThatArrive) {
    // A narrow rim far behind the stop clips the off-axis bundle on one side.
    const LensSystem lens = buildRows({stopRow(5, 12), row(60, 6, 1.5168, 30), row(0, 30, 0, 30), row(0, 60, 0, 14)});
    const LensAnalysis a = analyzeLens(lens, std::nullopt, kInf);
    const std::optional<FieldAim> aim = aimField(a.lens, {12, kInf});
    ASSERT_TRUE(aim);
    const ImageRays rays = settledImageRays(a.lens, *aim, a.focus.imageZExact, {}, 0.002, 256);
    const SpotDiagram spot = spotDiagram(rays, a.focus.imageZExact, {0, 0});
    ASSERT_GT(spot.points.size(), 10u);
    ASSERT_LT(spot.transmission, 0.95) << "the field must be vignetted";
    ASSERT_GT(spot.transmission, 0.05);
    double w = 0, cx = 0, cy = 0;
    for (std::size_t i = 0; i < spot.points.size(); ++i) {
        w += spot.weights[i];
        cx += spot.weights[i] * spot.points[i].x;
        cy += spot.weights[i] * spot.points[i].y;
    }
    EXPECT_NEAR(w, spot.transmission, 1e-12);
    cx /= w;
    cy /= w;
    double sum = 0;
    for (std::size_t i = 0; i < spot.points.size(); ++i)
        sum += spot.weights[i] * ((spot.points[i].x - cx) * (spot.points[i].x - cx) + (spot.points[i].y - cy) * (spot.points[i].y - cy));
    EXPECT_NEAR(spot.statistics.rmsRadius, std::sqrt(sum / w), 1e-12);
}

// Rays spread along y only (the tangential direction): the sagittal MTF is 1, the tangential one
// that of two lines 2a apart, |cos(2 pi nu a)|.
TEST(GeometricMtf, SagittalAlongXTangentialAlongY) {
    SpotDiagram spot;
    const double a = 0.01;  // mm
    spot.points = {{0, -a}, {0, a}, {0, -a}, {0, a}};
    spot.weights = {0.25, 0.25, 0.25, 0.25};
    spot.raysLaunched = 4;
    const std::vector<double> nu = {0, 5, 12.5, 20, 37.5, 50};
    const std::vector<double> s = geometricMtf({spot}, {1}, MtfDirection::Sagittal, nu);
    const std::vector<double> t = geometricMtf({spot}, {1}, MtfDirection::Tangential, nu);
    for (std::size_t k = 0; k < nu.size(); ++k) {
        EXPECT_NEAR(s[k], 1, 1e-12) << nu[k];
        EXPECT_NEAR(t[k], std::fabs(std::cos(2 * 3.14159265358979323846 * nu[k] * a)), 1e-12) << nu[k];
    }
}

// A perfect lens's image plane moved by dz: the wavefront is pure defocus, W = dz (1 - cos u), about
// dz NA^2 rho^2 / 2 at small NA; with its piston (mean) removed its RMS over the pupil is
// W20 / sqrt(12) (about zero it would be W20 / sqrt(3), twice as much).
TEST(WavefrontMap, DefocusRmsHasThePistonRemoved) {
    const double n = 1.5, fstop = 8, dz = 0.2;
    const LensAnalysis a = analyzeLens(planoConvex(n, 100, -n * n), fstop, kInf);
    const std::optional<FieldAim> aim = aimField(a.lens, {0, kInf});
    ASSERT_TRUE(aim);
    for (double shift : {dz, -dz}) {
        const std::optional<WavefrontMap> w = wavefrontMap(a.lens, *aim, a.focus.imageZExact + shift, a.pupils.exit.z, {64, 4});
        ASSERT_TRUE(w);
        const double na = 1 / (2 * fstop), w20 = dz * na * na / 2 / (kWavelengthD * 1e-6);
        EXPECT_NEAR(w->rmsWaves, w20 / std::sqrt(12.0), 0.03 * w20 / std::sqrt(12.0)) << shift;
    }
}

// The foci of thin fans about the chief ray, against Coddington's equations carried along the chief
// ray by hand: at the sphere (object at infinity) t' = n cos^2 I' R / (n cos I' - cos I) and
// s' = n R / (n cos I' - cos I); at the flat face t' = t cos^2 I' / (n cos^2 I), s' = s / n.
TEST(FieldCurvature, TangentialAndSagittalFociFollowCoddington) {
    const HandSinglet singlet;
    const LensSystem lens = singlet.lens();
    const double n = lens.surfaces[1].indexAfter, imageZ = -singlet.stopGap - singlet.thickness - 90;
    for (double field : {5.0, 10.0, 15.0}) {
        Ray2 r{0, 0, std::sin(field * kDegree), -std::cos(field * kDegree)};
        double ny, nz;
        const Ray2 atSphere = toSphere(r, -singlet.stopGap, singlet.radius, ny, nz);
        const double cosI = std::fabs(r.dy * ny + r.dz * nz);
        const Ray2 inGlass = refracted(atSphere, ny, nz, 1, n);
        const double cosIPrime = std::fabs(inGlass.dy * ny + inGlass.dz * nz);
        const double power = (n * cosIPrime - cosI) / singlet.radius;
        const double t1 = n * cosIPrime * cosIPrime / power, s1 = n / power;
        const Ray2 atFlat = toPlane(inGlass, -singlet.stopGap - singlet.thickness);
        const double d = std::hypot(atFlat.y - atSphere.y, atFlat.z - atSphere.z);
        const Ray2 out = refracted(atFlat, 0, 1, n, 1);
        const double cos2 = std::fabs(atFlat.dz), cos2Prime = std::fabs(out.dz);
        const double t2 = (t1 - d) * cos2Prime * cos2Prime / (n * cos2 * cos2), s2 = (s1 - d) / n;
        const double tangentialZ = atFlat.z + t2 * out.dz, sagittalZ = atFlat.z + s2 * out.dz;

        const std::vector<FieldCurvatureSample> samples = fieldCurvature(lens, kInf, imageZ, {field});
        ASSERT_TRUE(samples.at(0).found) << field;
        EXPECT_NEAR(samples[0].tangentialZ, tangentialZ, 1e-4) << field;
        EXPECT_NEAR(samples[0].sagittalZ, sagittalZ, 1e-4) << field;
        EXPECT_NEAR(samples[0].tangentialShift, tangentialZ - imageZ, 1e-4) << field;
        EXPECT_NEAR(samples[0].sagittalShift, sagittalZ - imageZ, 1e-4) << field;
        EXPECT_GT(std::fabs(tangentialZ - sagittalZ), 0.05) << "astigmatic at " << field << " degrees";
    }
}
