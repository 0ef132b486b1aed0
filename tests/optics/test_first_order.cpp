// First-order data (cardinal points, pupils, f-number, focus) against an independent paraxial y-nu
// trace and the published figures.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "firstorder/Aperture.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Focus.h"
#include "settings/LensAnalysis.h"
#include "prescription/OpticsError.h"
#include "ParaxialYNu.h"
#include "firstorder/Pupils.h"
#include "firstorder/ThickLens.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {


std::vector<std::string> publishedTables() {
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::directory_iterator(std::string(LENSLAB_SOURCE_DIR) + "/lenses"))
        if (e.path().extension() == ".dat") paths.push_back(e.path().string());
    return paths;
}

struct Reference {
    double efl, zF, zFPrime, zP, zPPrime;
};

Reference ynuFirstOrder(const LensSystem& lens) {
    const int n = static_cast<int>(lens.surfaces.size());
    // Parallel ray from the scene: F' where it crosses the axis, P' where its extension is at y0.
    const auto fwd = ynuSystem(lens, 0, n, false);
    const YNu a = traceYNu(fwd, fwd.front().s - 1, 1.0, 0.0);
    const double eflBack = -1.0 / a.u;
    const double zFPrime = -axisCrossing(a);
    // Parallel ray from the film side, in the reversed frame (+s = +z).
    const auto rev = ynuSystem(lens, 0, n, true);
    const YNu b = traceYNu(rev, rev.front().s - 1, 1.0, 0.0);
    const double zF = axisCrossing(b);
    return {eflBack, zF, zFPrime, zF - (-1.0 / b.u), zFPrime + eflBack};
}

}  // namespace

TEST(FirstOrder, MatchesIndependentYNuTraceForEveryPublishedTable) {
    const auto tables = publishedTables();
    ASSERT_GE(tables.size(), 8u);
    for (const auto& path : tables) {
        SCOPED_TRACE(path);
        const LensSystem lens = loadLensSystem(path);
        const FirstOrder fo = computeFirstOrder(lens);
        const Reference ref = ynuFirstOrder(lens);
        EXPECT_NEAR(fo.efl / ref.efl, 1.0, 1e-9);
        EXPECT_NEAR(fo.eflFront / ref.efl, 1.0, 1e-9);
        const double tol = 1e-9 * ref.efl;
        EXPECT_NEAR(fo.zFPrime, ref.zFPrime, tol);
        EXPECT_NEAR(fo.zF, ref.zF, tol);
        EXPECT_NEAR(fo.zPPrime, ref.zPPrime, tol);
        EXPECT_NEAR(fo.zP, ref.zP, tol);
        EXPECT_NEAR(fo.backFocalDistance, lens.rearZ() - ref.zFPrime, tol);
    }
}

TEST(FirstOrder, PublishedFigures) {
    const std::string dir = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
    const FirstOrder d50 = computeFirstOrder(loadLensSystem(dir + "dgauss.50mm.dat"));
    EXPECT_NEAR(d50.efl, 50.358, 5e-4);
    EXPECT_NEAR(d50.backFocalDistance, 36.106, 5e-4);
    const LensSystem d50lens = loadLensSystem(dir + "dgauss.50mm.dat");
    EXPECT_NEAR(d50.zPPrime - d50lens.rearZ(), 14.2523, 1e-4);  // P' in front of the rear vertex (pbrt-v3 log)
    EXPECT_NEAR(computeFirstOrder(loadLensSystem(dir + "dgauss.dat")).efl, 100.72, 5e-3);
    EXPECT_NEAR(computeFirstOrder(loadLensSystem(dir + "wide.dat")).efl, 100.11, 5e-3);
    EXPECT_NEAR(computeFirstOrder(loadLensSystem(dir + "telephoto.dat")).efl, 99.83, 5e-3);
    EXPECT_NEAR(computeFirstOrder(loadLensSystem(dir + "fisheye.dat")).efl, 99.91, 5e-3);
}

TEST(Pupils, MatchIndependentYNuImagesOfTheStop) {
    for (const auto& path : publishedTables()) {
        SCOPED_TRACE(path);
        const LensSystem lens = loadLensSystem(path);
        const Pupils p = computePupils(lens);
        const int s = lens.stopIndex, n = static_cast<int>(lens.surfaces.size());
        const double stopD = 2 * lens.stop().apertureRadius, u0 = 0.01;
        // Entrance: from the stop centre toward the scene, in the reversed frame (+s = +z).
        const auto front = ynuSystem(lens, 0, s, true);
        const YNu e = traceYNu(front, lens.stop().z, 0.0, u0);
        EXPECT_NEAR(p.entrance.z, front.empty() ? lens.stop().z : axisCrossing(e), 1e-8);
        EXPECT_NEAR(p.entrance.diameter, stopD * std::fabs(u0 / e.u), 1e-8);
        // Exit: from the stop centre toward the film (+s = -z).
        const auto back = ynuSystem(lens, s + 1, n, false);
        const YNu x = traceYNu(back, -lens.stop().z, 0.0, u0);
        EXPECT_NEAR(p.exit.z, back.empty() ? lens.stop().z : -axisCrossing(x), 1e-8);
        EXPECT_NEAR(p.exit.diameter, stopD * std::fabs(u0 / x.u), 1e-8);
    }
}

TEST(Aperture, FNumberRangesOfTheBundledLenses) {
    // The designs are published as f/2, f/2.8, f/5.6 and f/4; the widest cone that every surface
    // passes lands close to those.
    const std::string dir = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
    const struct {
        const char* name;
        double fstopMin;
    } cases[] = {{"dgauss.50mm", 2.0198}, {"wide.22mm", 2.7883}, {"telephoto.250mm", 5.5928}, {"fisheye.10mm", 3.9937}};
    for (const auto& c : cases) {
        const LensSystem lens = loadLensSystem(dir + c.name + ".dat");
        const FirstOrder fo = computeFirstOrder(lens);
        EXPECT_NEAR(computeApertureRange(lens, fo).fstopMin, c.fstopMin, 1e-4) << c.name;
    }
}

TEST(Aperture, StopDiameterGivesTheRequestedConeAndEntrancePupil) {
    const LensSystem lens = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    const FirstOrder fo = computeFirstOrder(lens);
    const ApertureRange range = computeApertureRange(lens, fo);
    for (double N : {2.8, 4.0, 8.0, 22.0}) {
        const double d = stopDiameterForFstop(lens, fo, range, N);
        const LensSystem stopped = withStopDiameter(lens, d);
        // Paraxially the entrance pupil is EFL / N; the real-ray definition differs by O(1/N^2).
        const double ep = computePupils(stopped).entrance.diameter;
        EXPECT_NEAR(ep, fo.efl / N, 0.02 * fo.efl / N / (N / 2.8)) << N;
        // Rays from the scene, parallel, at 99.9% of the pupil pass; at 100.1% the stop clips them.
        const Pupil entrance = computePupils(stopped).entrance;
        auto passes = [&](double frac) {
            const Ray r{{0, frac * 0.5 * entrance.diameter, 5.0}, {0, 0, -1}};
            return traceRay(stopped, r, TraceDirection::SceneToFilm).ok();
        };
        EXPECT_TRUE(passes(0.99));
        EXPECT_FALSE(passes(1.05));
    }
}

TEST(Aperture, OutOfRangeFNumberNamesTheRange) {
    const LensSystem lens = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    const FirstOrder fo = computeFirstOrder(lens);
    const ApertureRange range = computeApertureRange(lens, fo);
    try {
        stopDiameterForFstop(lens, fo, range, 1.4);
        FAIL();
    } catch (const OpticsError& e) {
        EXPECT_STREQ(e.what(), "f-number 1.4 is outside this lens's range f/2.02 to f/64");
    }
    EXPECT_THROW(stopDiameterForFstop(lens, fo, range, 64.01), OpticsError);
    EXPECT_THROW(stopDiameterForFstop(lens, fo, range, std::nan("")), OpticsError);
    EXPECT_NEAR(stopDiameterForFstop(lens, fo, range, range.fstopMin), range.stopDiameterMax, 1e-9);
}

TEST(Aperture, FullAndFineStops) {
    const auto full = fullStops(2.0198, 16);
    ASSERT_EQ(full.size(), 6u);  // 2.83 4 5.66 8 11.3 16
    EXPECT_NEAR(full.front(), 2 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(full.back(), 16, 1e-12);
    const auto fine = fineStops(2.0198, 2.5);
    ASSERT_EQ(fine.size(), 5u);  // 2.1 .. 2.5
    EXPECT_NEAR(fine.front(), 2.1, 1e-12);
}

TEST(Focus, ThickLensImageMatchesYNuAndExactConvergesNearIt) {
    for (const auto& path : publishedTables()) {
        SCOPED_TRACE(path);
        const LensSystem table = loadLensSystem(path);
        const FirstOrder fo = computeFirstOrder(table);
        const ApertureRange range = computeApertureRange(table, fo);
        // A small stop: the exact best focus then sits on the paraxial image.
        const LensSystem lens = withStopDiameter(table, stopDiameterForFstop(table, fo, range, 32));
        const Pupils pupils = computePupils(lens);
        const double distance = 20 * fo.efl;
        const FocusResult f = focusAt(lens, fo, pupils, distance);
        const auto fwd = ynuSystem(lens, 0, static_cast<int>(lens.surfaces.size()), false);
        const YNu r = traceYNu(fwd, -distance, 0.0, 0.001);
        EXPECT_NEAR(f.imageZThick, -axisCrossing(r), 1e-8 * fo.efl);
        EXPECT_NEAR(f.imageZExact, f.imageZThick, 2e-3 * fo.efl);
        EXPECT_GT(f.raysUsed, 32);
        const FocusResult inf = focusAt(lens, fo, pupils, kInf);
        EXPECT_TRUE(inf.infinity);
        EXPECT_DOUBLE_EQ(inf.imageZThick, fo.zFPrime);
        EXPECT_NEAR(inf.imageZExact, fo.zFPrime, 2e-3 * fo.efl);
    }
}

TEST(Focus, FullApertureBestFocusShowsSphericalAberration) {
    const LensAnalysis a = analyzeLens(loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"),
                                       std::nullopt, kInf);
    // At f/2 the marginal rays' spherical aberration moves the least-RMS focus off the paraxial
    // F' by a measurable but small amount.
    EXPECT_GT(std::fabs(a.focus.difference), 1e-3);
    EXPECT_LT(std::fabs(a.focus.difference), 0.5);
}

TEST(Focus, RefusesDistancesItCannotReach) {
    const LensSystem table = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat");
    const FirstOrder fo = computeFirstOrder(table);
    const Pupils pupils = computePupils(table);
    const double ffd = fo.zF - table.frontZ();
    try {
        focusAt(table, fo, pupils, 0.9 * ffd);
        FAIL();
    } catch (const OpticsError& e) {
        EXPECT_NE(std::string(e.what()).find("inside the front focal length"), std::string::npos) << e.what();
    }
    const double closest = closestFocusDistance(fo) - table.frontZ();
    try {
        focusAt(table, fo, pupils, 0.5 * (ffd + closest));
        FAIL();
    } catch (const OpticsError& e) {
        EXPECT_NE(std::string(e.what()).find("closer than this lens can focus"), std::string::npos) << e.what();
    }
    EXPECT_THROW(focusAt(table, fo, pupils, -100), OpticsError);
    EXPECT_THROW(focusAt(table, fo, pupils, std::nan("")), OpticsError);
    const FocusResult near = focusAt(table, fo, pupils, closest);
    EXPECT_TRUE(std::isfinite(near.imageZExact));
    EXPECT_LT(near.imageZExact, table.rearZ());
}

TEST(ThickLens, MatricesAreInversesAndImageByTheLensEquation) {
    const LensAnalysis a = analyzeLens(loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/telephoto.250mm.dat"),
                                       std::nullopt, kInf);
    const Matrix4 t = objectToImageMatrix(a.thick), inv = imageToObjectMatrix(a.thick);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double v = 0;
            for (int k = 0; k < 4; ++k) v += t[i][k] * inv[k][j];
            EXPECT_NEAR(v, i == j ? 1.0 : 0.0, 1e-12);
        }
    // An object 3 m in front of P, 100 mm off axis: 1/s + 1/s' = 1/f and magnification -s'/s.
    const double f = a.firstOrder.efl, s = 3000, y = 100;
    const double p[4] = {0, y, a.firstOrder.zP + s, 1};
    double h[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) h[i] += t[i][k] * p[k];
    const double sImage = 1 / (1 / f - 1 / s);
    EXPECT_NEAR(h[2] / h[3], a.firstOrder.zPPrime - sImage, 1e-9);
    EXPECT_NEAR(h[1] / h[3], -y * sImage / s, 1e-9);
}
