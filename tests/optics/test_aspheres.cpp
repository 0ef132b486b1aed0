// Conic and even-aspheric surfaces: the exact trace meets the sag equation and Snell's law, a
// Cartesian (hyperbolic) singlet is free of spherical aberration where its spherical twin is not,
// scalar and batch agree to the bit, and the paraxial data see only the vertex curvature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "settings/LensAnalysis.h"
#include "ParaxialYNu.h"
#include "PrescriptionRows.h"
#include "trace/RayBatch.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

// RMS distance from the axis, on the plane z, of a collimated on-axis bundle filling `radius`.
double rmsSpotOnAxis(const LensSystem& lens, double radius, double z) {
    double sum = 0;
    int count = 0;
    for (int i = -20; i <= 20; ++i)
        for (int j = -20; j <= 20; ++j) {
            const double x = radius * i / 20, y = radius * j / 20;
            if (x * x + y * y > radius * radius) continue;
            const TraceResult r = traceRay(lens, {{x, y, 5}, {0, 0, -1}}, TraceDirection::SceneToFilm);
            EXPECT_TRUE(r.ok()) << x << " " << y << " " << blockReasonName(r.blocked);
            const double t = (z - r.ray.origin.z) / r.ray.direction.z;
            const Vec3 p = pointAt(r.ray, t);
            sum += p.x * p.x + p.y * p.y;
            ++count;
        }
    return std::sqrt(sum / count);
}

// A strong even asphere on a biconvex lens: conic, r^4, r^6 and r^8 terms on the front.
LensSystem asphericLens() {
    LensTableRow front = row(40, 6, 1.6, 30);
    front.conic = -0.8;
    front.aspheric = {0, -2e-5, 3e-8, -1e-11, 0, 0, 0, 0};
    return buildRows({front, row(-120, 2, 0, 30), stopRow(30, 20)});
}

Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

}  // namespace

TEST(Aspheres, SagFollowsTheEvenAsphereFormula) {
    Surface s;
    s.curvature = 1.0 / 50;
    s.conic = -0.5;
    s.aspheric = {1e-4, 2e-6, -3e-9, 0, 0, 0, 0, 1e-20};
    const double h = 12;
    const double c = s.curvature, r2 = h * h;
    const double expected = c * r2 / (1 + std::sqrt(1 - 0.5 * c * c * r2)) + 1e-4 * r2 + 2e-6 * r2 * r2 -
                            3e-9 * r2 * r2 * r2 + 1e-20 * std::pow(h, 16);
    EXPECT_NEAR(sag(s, h), expected, 1e-13);
    // The conic's domain: 1 / (c sqrt(1 + k)).
    EXPECT_NEAR(sagDomainRadius(s), 50 / std::sqrt(0.5), 1e-12);
    s.conic = -1;
    EXPECT_TRUE(std::isinf(sagDomainRadius(s)));
    EXPECT_DOUBLE_EQ(s.vertexCurvature(), 1.0 / 50 + 2e-4);
}

TEST(Aspheres, HyperbolicSingletFocusesACollimatedBundleToAPoint) {
    // Leaving glass of index n, a hyperboloid of eccentricity n (conic -n^2) sends rays parallel to
    // its axis to one point (Descartes): the exact spot is rounding only. The sphere is not.
    const double n = 1.5, f = 100;
    const LensSystem hyperbolic = planoConvex(n, f, -n * n);
    const LensSystem spherical = planoConvex(n, f, 0);
    const FirstOrder foH = computeFirstOrder(hyperbolic);
    const FirstOrder foS = computeFirstOrder(spherical);
    // Paraxially the conic changes nothing: f = R / (n - 1) for both.
    EXPECT_NEAR(foH.efl, f, 1e-7 * f);
    EXPECT_NEAR(foS.efl, f, 1e-7 * f);
    EXPECT_NEAR(foH.zFPrime, foS.zFPrime, 1e-7 * f);
    const double beam = 0.35 * (n - 1) * f;
    EXPECT_LT(rmsSpotOnAxis(hyperbolic, beam, foH.zFPrime), 1e-6 * f);
    EXPECT_GT(rmsSpotOnAxis(spherical, beam, foS.zFPrime), 1e-3 * f);
}

TEST(Aspheres, TracedRayMeetsTheSagAndObeysSnellsLaw) {
    const LensSystem lens = asphericLens();
    const Surface& s = lens.surfaces[0];
    int checked = 0;
    for (int i = 0; i <= 12; ++i)
        for (int k = 0; k < 3; ++k) {
            const double h = 14.5 * i / 12;
            // Aimed to cross the vertex plane at height h, from 20 mm in front.
            const Vec3 d = normalize(Vec3{0.02 * k, -0.15 + 0.1 * k, -1});
            const Ray start{{0.3 * k - 20 * d.x / d.z, h - 20 * d.y / d.z, 20}, d};
            std::vector<Vec3> path;
            TraceOptions o;
            o.end = 1;
            o.path = &path;
            const TraceResult r = traceRay(lens, start, TraceDirection::SceneToFilm, o);
            if (!r.ok()) continue;
            ASSERT_EQ(path.size(), 2u);
            const Vec3 hit = path[1];
            const double rho = std::hypot(hit.x, hit.y);
            // On the surface: qz = -sag(r).
            EXPECT_NEAR(hit.z - s.z, -sag(s, rho), 1e-9) << h;
            // The normal from the sag by central differences, written here independently.
            const double e = 1e-5;
            const double dsdr = (sag(s, rho + e) - sag(s, rho - e)) / (2 * e);
            const Vec3 normal = normalize(rho > 0 ? Vec3{dsdr * hit.x / rho, dsdr * hit.y / rho, 1} : Vec3{0, 0, 1});
            auto sine = [&](Vec3 v) { return length(cross(v, normal)); };
            EXPECT_NEAR(1.0 * sine(start.direction), 1.6 * sine(r.ray.direction), 1e-8) << h;
            EXPECT_NEAR(dot(cross(start.direction, r.ray.direction), normal), 0, 1e-9);
            EXPECT_NEAR(length(r.ray.direction), 1, 1e-14);
            ++checked;
        }
    EXPECT_GT(checked, 30);
}

TEST(Aspheres, ForwardThenBackReturnsToItself) {
    const LensSystem lens = asphericLens();
    for (double h : {0.5, 4.0, 9.0}) {
        const Ray in{{0.7, h, 10}, normalize(Vec3{0.01, -0.05, -1})};
        const TraceResult fwd = traceRay(lens, in, TraceDirection::SceneToFilm);
        ASSERT_TRUE(fwd.ok()) << h;
        const TraceResult back =
            traceRay(lens, {fwd.ray.origin, -fwd.ray.direction}, TraceDirection::FilmToScene);
        ASSERT_TRUE(back.ok());
        // Back at the front surface; extend to the start plane.
        const double t = (in.origin.z - back.ray.origin.z) / back.ray.direction.z;
        const Vec3 p = pointAt(back.ray, t);
        EXPECT_NEAR(p.x, in.origin.x, 1e-10);
        EXPECT_NEAR(p.y, in.origin.y, 1e-10);
        EXPECT_NEAR(back.ray.direction.y, -in.direction.y, 1e-12);
    }
}

TEST(Aspheres, BatchEqualsScalarBitForBit) {
    const LensSystem lens = asphericLens();
    RayBatch batch;
    const int n = 257;
    batch.resize(n);
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        const double u = double(i) / (n - 1);
        rays.push_back({{3 * std::sin(7.0 * i), -16 + 32 * u, 15}, normalize(Vec3{0.05 * std::cos(3.0 * i), -0.2 * u, -1})});
        batch.set(i, rays.back());
    }
    traceBatch(lens, batch, TraceDirection::SceneToFilm);
    int passed = 0;
    for (int i = 0; i < n; ++i) {
        const TraceResult r = traceRay(lens, rays[i], TraceDirection::SceneToFilm);
        ASSERT_EQ(r.blocked, batch.blocked[i]) << i;
        const Ray b = batch.get(i);
        EXPECT_EQ(0, std::memcmp(&r.ray, &b, sizeof(Ray))) << i;
        passed += r.ok();
    }
    EXPECT_GT(passed, n / 2);
    EXPECT_LT(passed, n);  // some rays leave the 30 mm front or the stop: both paths must agree on them too
}

// The exit-pupil search's batches through the Sony 55 mm's five aspheres: rays from a film point
// toward a wide grid, most blocked at the rear elements, some passing, some alive at an asphere
// they miss (Newton never converges: all 32 iterations). The batch drops blocked rays from Newton
// and finishes the last few iterating rays apart from the whole batch: each must still take the
// scalar trace's steps to the bit.
TEST(Aspheres, BatchWithSlowAndBlockedRaysEqualsScalarBitForBit) {
    const LensSystem lens = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us2015-0092100-ex1-55mm.zmx");
    const double filmZ = lens.rearZ() - 1.0;
    const int side = 48, n = side * side;
    RayBatch batch;
    batch.resize(n);
    std::vector<Ray> rays;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const Vec3 from{6.0, 0.0, filmZ};
            const Vec3 to{-40 + 80.0 * (i + 0.5) / side, -40 + 80.0 * (j + 0.5) / side, lens.frontZ()};
            rays.push_back({from, normalize(to - from)});
            batch.set(rays.size() - 1, rays.back());
        }
    traceBatch(lens, batch, TraceDirection::FilmToScene);
    int passed = 0, missedAnAsphere = 0;
    for (int i = 0; i < n; ++i) {
        const TraceResult r = traceRay(lens, rays[i], TraceDirection::FilmToScene);
        ASSERT_EQ(r.blocked, batch.blocked[i]) << i;
        const Ray b = batch.get(i);
        EXPECT_EQ(0, std::memcmp(&r.ray, &b, sizeof(Ray))) << i;
        passed += r.ok();
        missedAnAsphere += r.blocked == BlockReason::MissedSurface && lens.surfaces[r.surface].isAspheric();
    }
    EXPECT_GT(passed, n / 20);
    EXPECT_LT(passed, n / 2);
    EXPECT_GT(missedAnAsphere, 0);
}

TEST(Aspheres, ParaxialDataSeeOnlyTheVertexCurvature) {
    // An r^2 term is a curvature: a sphere of c + 2 a2 has the same first order; higher terms none.
    LensTableRow front = row(60, 5, 1.7, 30);
    front.aspheric = {1.0 / 400, 4e-6, -1e-8, 0, 0, 0, 0, 0};
    const LensSystem asphere = buildRows({front, row(-80, 2, 0, 30), stopRow(30, 20)});
    const double c = 1.0 / 60 + 2.0 / 400;
    const LensSystem twin = buildRows({row(1 / c, 5, 1.7, 30), row(-80, 2, 0, 30), stopRow(30, 20)});
    const FirstOrder a = computeFirstOrder(asphere), b = computeFirstOrder(twin);
    EXPECT_NEAR(a.efl, b.efl, 1e-8);
    EXPECT_NEAR(a.zFPrime, b.zFPrime, 1e-8);
    EXPECT_NEAR(a.zP, b.zP, 1e-8);
    // And the independent y-nu trace agrees (it reads the vertex curvature).
    const auto sys = test::ynuSystem(asphere, 0, int(asphere.surfaces.size()), false);
    const test::YNu out = test::traceYNu(sys, -10, 1e-3, 0);
    EXPECT_NEAR(-test::axisCrossing(out), a.zFPrime, 1e-8);
}

TEST(Aspheres, ApertureBeyondTheConicsDomainIsRefusedNamingTheSurface) {
    // A prolate ellipsoid (k = 0.5) of R 20 is defined out to 20 / sqrt(1.5) = 16.33 mm.
    LensTableRow front = row(20, 5, 1.5, 34);
    front.conic = 0.5;
    try {
        buildRows({front, row(0, 2, 0, 34), stopRow(10, 10)});
        FAIL() << "accepted a clear aperture past the conic's edge";
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 1);
        EXPECT_NE(std::string(e.what()).find("conic"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("32.6599"), std::string::npos) << e.what();
    }
}

TEST(Aspheres, AnalysisOfAnAsphericLensIsFinite) {
    const LensAnalysis a = analyzeLens(asphericLens(), std::nullopt, 2000);
    for (double v : {a.firstOrder.efl, a.pupils.entrance.z, a.focus.imageZExact, a.fstop})
        EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(a.focus.raysUsed, 48);  // of 64 rings
}

TEST(Aspheres, AHemisphereReachesItsRimExactly) {
    // Diameter 2|R|: at the rim 1 - c^2 h^2 rounds a few ulp below 0; the sag is still R there (a
    // fuzzer found the NaN this used to give).
    const LensSystem lens = buildLensSystem(parseLensTable("10 0 1.5 20\n0 5 0 10\n", "hemisphere.dat"));
    EXPECT_DOUBLE_EQ(sag(lens.surfaces[0], 10), 10);
    EXPECT_TRUE(std::isnan(sag(lens.surfaces[0], 10.001)));
}

TEST(Aspheres, NewtonStartsOnTheVertexPlaneWhereTheBaseConicIsMissed) {
    // A ray parallel to the axis 20 mm out misses the base sphere of radius 10; Newton then starts
    // where the ray crosses the vertex plane: 5 mm ahead of a start 5 mm in front of it.
    SurfaceConstants<double> s;
    s.curvature = 0.1;
    s.radius = 10;
    s.asphericTerms = 2;
    s.aspheric[1] = 1e-4;
    EXPECT_DOUBLE_EQ(asphereStart(20.0, 0.0, 5.0, 0.0, 0.0, -1.0, s), 5.0);
    // Where the conic is hit, the start is that hit: on axis, the vertex itself.
    EXPECT_DOUBLE_EQ(asphereStart(0.0, 0.0, 5.0, 0.0, 0.0, -1.0, s), 5.0);
}
