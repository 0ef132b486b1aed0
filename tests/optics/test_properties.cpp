// Invariants on random valid lenses: reversibility, the thick lens as the paraxial limit of the
// exact trace, finiteness, and blocked rays that say why.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "prescription/OpticsError.h"
#include "firstorder/Pupils.h"
#include "RandomLens.h"
#include "firstorder/ThickLens.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

constexpr int kLenses = 300;

// A film-side ray aimed at a random point of the rear surface's aperture.
Ray randomFilmRay(const LensSystem& lens, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    const double r = lens.surfaces.back().apertureRadius;
    const Vec3 film{u(rng) * r, u(rng) * r, lens.rearZ() - 20 - 30 * std::fabs(u(rng))};
    const Vec3 target{u(rng) * r, u(rng) * r, lens.rearZ()};
    return {film, normalize(target - film)};
}

}  // namespace

TEST(Properties, ForwardThenBackwardReturnsTheRay) {
    std::mt19937_64 rng(1);
    int passed = 0;
    for (int k = 0; k < kLenses; ++k) {
        const LensSystem lens = randomLens(rng);
        for (int j = 0; j < 20; ++j) {
            const Ray in = randomFilmRay(lens, rng);
            const TraceResult out = traceRay(lens, in, TraceDirection::FilmToScene);
            if (!out.ok()) continue;
            // Reverse the outgoing ray, trace it back, and carry it to the film plane it started on.
            const TraceResult back = traceRay(lens, {out.ray.origin, -out.ray.direction}, TraceDirection::SceneToFilm);
            ASSERT_TRUE(back.ok()) << "lens " << k;
            const double t = (in.origin.z - back.ray.origin.z) / back.ray.direction.z;
            const Vec3 p = pointAt(back.ray, t);
            ASSERT_NEAR(p.x, in.origin.x, 1e-9);
            ASSERT_NEAR(p.y, in.origin.y, 1e-9);
            ASSERT_NEAR(-back.ray.direction.x, in.direction.x, 1e-12);
            ASSERT_NEAR(-back.ray.direction.y, in.direction.y, 1e-12);
            ++passed;
        }
    }
    EXPECT_GT(passed, kLenses * 2);
}

TEST(Properties, ThickLensIsTheNearAxisLimitOfTheExactTrace) {
    std::mt19937_64 rng(2);
    int checked = 0;
    for (int k = 0; k < kLenses; ++k) {
        const LensSystem lens = randomLens(rng);
        FirstOrder fo;
        Pupils pupils;
        try {
            fo = computeFirstOrder(lens);
            pupils = computePupils(lens);
        } catch (const OpticsError&) {
            continue;  // afocal or telecentric draws have no thick-lens model
        }
        if (!(fo.efl > 1) || fo.efl > 1e4) continue;
        const ThickLens thick = makeThickLens(fo, pupils);
        const double h = 1e-2 * lens.surfaces.front().apertureRadius;
        const auto e = thickLensError(lens, thick, fo, {h, h / 10});
        if (e[0].blocked || e[1].blocked) continue;
        // Transverse error at the focal plane goes as h^3, angle error as h^3 too (third-order aberrations).
        EXPECT_LT(std::fabs(e[1].transverseError), 2e-3 * std::fabs(e[0].transverseError) + 1e-12) << k;
        EXPECT_LT(std::fabs(e[1].angleError), 2e-3 * std::fabs(e[0].angleError) + 1e-14) << k;
        EXPECT_LT(std::fabs(e[1].transverseError), 1e-6 * fo.efl) << k;
        ++checked;
    }
    EXPECT_GT(checked, kLenses / 3);
}

TEST(Properties, NoNaNAnywhereAndBlockedRaysSayWhy) {
    std::mt19937_64 rng(3);
    int blocked = 0, total = 0;
    for (int k = 0; k < kLenses; ++k) {
        const LensSystem lens = randomLens(rng);
        for (int j = 0; j < 50; ++j) {
            const Ray in = randomFilmRay(lens, rng);
            const TraceResult r = traceRay(lens, in, TraceDirection::FilmToScene);
            ASSERT_TRUE(isFinite(r.ray.origin) && isFinite(r.ray.direction)) << k;
            ASSERT_NEAR(length(r.ray.direction), 1, 1e-12);
            if (r.ok()) {
                ASSERT_EQ(r.surface, -1);
            } else {
                ASSERT_GE(r.surface, 0);
                ASSERT_LT(r.surface, static_cast<int>(lens.surfaces.size()));
                ASSERT_STRNE(blockReasonName(r.blocked), "unknown");
                ++blocked;
            }
            ++total;
        }
        try {
            const FirstOrder fo = computeFirstOrder(lens);
            for (double v : {fo.efl, fo.zF, fo.zFPrime, fo.zP, fo.zPPrime}) ASSERT_TRUE(std::isfinite(v)) << k;
        } catch (const OpticsError& e) {
            ASSERT_GT(std::string(e.what()).size(), 10u);  // an afocal draw is refused in words
        }
    }
    EXPECT_GT(blocked, 0);
    EXPECT_LT(blocked, total);
}
