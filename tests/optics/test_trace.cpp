// The exact tracer: Snell's law, blocking reasons, the batched interface, recorded paths.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "trace/ExactTrace.h"
#include "trace/RayBatch.h"

using namespace lenslab;

namespace {

LensSystem builtTable(const std::string& text) { return buildLensSystem(parseLensTable(text, "t.dat")); }

const std::string kDgauss = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat";

}  // namespace

TEST(Trace, AxialRayStaysOnTheAxis) {
    const LensSystem lens = loadLensSystem(kDgauss);
    const TraceResult r = traceRay(lens, {{0, 0, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.ray.origin.x, 0);
    EXPECT_EQ(r.ray.origin.y, 0);
    EXPECT_DOUBLE_EQ(r.ray.origin.z, lens.rearZ());
    EXPECT_EQ(r.ray.direction.z, -1);
}

TEST(Trace, SingleSurfaceObeysSnellsLaw) {
    // A convex glass surface (R = 30) then the stop: check n1 sin(i) = n2 sin(r) about the normal.
    const LensSystem lens = builtTable("30 0 1.7 40\n0 10 0 30\n");
    const Ray in{{0, 0, 20}, normalize({0.05, -0.4, -1})};
    std::vector<Vec3> path;
    TraceOptions o;
    o.end = 1;
    o.path = &path;
    const TraceResult r = traceRay(lens, in, TraceDirection::SceneToFilm, o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(path.size(), 2u);
    const Vec3 hit = path[1];
    const Vec3 centre{0, 0, -30};
    EXPECT_NEAR(length(hit - centre), 30, 1e-12);  // on the sphere
    const Vec3 normal = normalize(hit - centre);
    auto sine = [&](Vec3 d) {
        const double c = dot(d, normal);
        return std::sqrt(1 - c * c);
    };
    EXPECT_NEAR(1.0 * sine(in.direction), 1.7 * sine(r.ray.direction), 1e-14);
    // Incident ray, refracted ray and normal are coplanar.
    const Vec3 a = in.direction, b = r.ray.direction;
    const Vec3 cross{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    EXPECT_NEAR(dot(cross, normal), 0, 1e-14);
    EXPECT_NEAR(length(r.ray.direction), 1, 1e-15);
}

TEST(Trace, ASteepRayMeetsAConcaveSurfaceWhereItCrossesIntoTheGlass) {
    // A face concave to the scene (R -5, centre 5 mm in front) and a ray at 62 deg through its
    // vertex: the ray's line also crosses the sphere 2.2 mm in front of the vertex, 4.14 mm off the
    // axis, going the other way (out of the glass side). Started in front of that point or behind
    // it, the ray meets the surface at the vertex.
    const LensSystem lens = builtTable("-5 0 1.5 8\n0 10 0 30\n");
    const double a = 62 * M_PI / 180;
    const Vec3 d{0, -std::sin(a), -std::cos(a)};
    for (double startZ : {1.0, 3.0, 4.5}) {
        std::vector<Vec3> path;
        TraceOptions o;
        o.end = 1;
        o.path = &path;
        const TraceResult r = traceRay(lens, {(startZ / d.z) * d, d}, TraceDirection::SceneToFilm, o);
        ASSERT_TRUE(r.ok()) << startZ;
        ASSERT_EQ(path.size(), 2u);
        EXPECT_NEAR(path[1].y, 0, 1e-12) << startZ;
        EXPECT_NEAR(path[1].z, 0, 1e-12) << startZ;
    }
}

TEST(Trace, TotalInternalReflectionIsReported) {
    // Leaving glass (n 1.8) through a flat face at 40 degrees: sin > 1/1.8, no refracted ray.
    const LensSystem lens = builtTable("0 0 1.8 40\n0 5 1 40\n0 5 0 30\n");
    const double a = 40 * M_PI / 180;
    const Ray in{{0, 0, -1}, {0, std::sin(a), -std::cos(a)}};
    TraceOptions o;
    o.begin = 1;
    const TraceResult r = traceRay(lens, in, TraceDirection::SceneToFilm, o);
    EXPECT_EQ(r.blocked, BlockReason::TotalInternalReflection);
    EXPECT_EQ(r.surface, 1);
    EXPECT_STREQ(blockReasonName(r.blocked), "total internal reflection");
    EXPECT_TRUE(isFinite(r.ray.origin) && isFinite(r.ray.direction));
}

TEST(Trace, ClippedRaysNameTheSurfaceAndReason) {
    const LensSystem lens = loadLensSystem(kDgauss);
    // Beyond the front element's 12.6 mm semi-aperture.
    TraceResult r = traceRay(lens, {{0, 13, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    EXPECT_EQ(r.blocked, BlockReason::OutsideAperture);
    EXPECT_EQ(r.surface, 0);
    // Through the front elements but outside the stop closed to 2 mm.
    const LensSystem stopped = withStopDiameter(lens, 2.0);
    r = traceRay(stopped, {{0, 5, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    EXPECT_EQ(r.blocked, BlockReason::ClippedByStop);
    EXPECT_EQ(r.surface, lens.stopIndex);
    // A ray that misses a strongly curved cap altogether.
    r = traceRay(builtTable("10 0 1.5 19\n0 5 0 10\n"), {{0, 30, 5}, {0, -0.01, -1}}, TraceDirection::SceneToFilm);
    EXPECT_NE(r.blocked, BlockReason::None);
}

TEST(Trace, BatchEqualsScalarBitForBit) {
    const LensSystem lens = loadLensSystem(kDgauss);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    RayBatch batch;
    batch.resize(4096);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < batch.size(); ++i) {
        const Vec3 film{u(rng) * 18, u(rng) * 12, -90};
        const Vec3 target{u(rng) * 14, u(rng) * 14, lens.rearZ()};
        rays.push_back({film, normalize(target - film)});
        batch.set(i, rays.back());
    }
    traceBatch(lens, batch, TraceDirection::FilmToScene);
    int blocked = 0;
    for (std::size_t i = 0; i < batch.size(); ++i) {
        const TraceResult s = traceRay(lens, rays[i], TraceDirection::FilmToScene);
        ASSERT_EQ(batch.blocked[i], s.blocked) << i;
        ASSERT_EQ(batch.blockedAt[i], s.surface) << i;
        const Ray b = batch.get(i);
        ASSERT_EQ(b.origin.x, s.ray.origin.x);
        ASSERT_EQ(b.origin.z, s.ray.origin.z);
        ASSERT_EQ(b.direction.y, s.ray.direction.y);
        blocked += !s.ok();
    }
    // The sample covers both outcomes.
    EXPECT_GT(blocked, 100);
    EXPECT_LT(blocked, 4000);
}

TEST(Trace, PathRecordsEverySurfaceHit) {
    const LensSystem lens = loadLensSystem(kDgauss);
    std::vector<Vec3> path;
    TraceOptions o;
    o.path = &path;
    ASSERT_TRUE(traceRay(lens, {{0, 3, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm, o).ok());
    ASSERT_EQ(path.size(), lens.surfaces.size() + 1);
    for (std::size_t i = 1; i < path.size(); ++i)
        EXPECT_NEAR(path[i].z, lens.surfaces[i - 1].z - sag(lens.surfaces[i - 1], std::hypot(path[i].x, path[i].y)), 1e-12);
}
