// Ghosts: the count of two-reflection paths per bundled lens against the reflecting surfaces
// counted here, every ghost's paraxial focus against an independent paraxial trace written here
// (the textbook convention: one global axis, the index changing sign at each reflection), and the
// exact-traced ghost of an uncoated biconvex lens against Gauss's conjugate equations surface by
// surface.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>

#include "PrescriptionRows.h"
#include "analysis/GhostAnalysis.h"
#include "prescription/OpticsError.h"
#include "trace/ExactTrace.h"
#include "trace/GhostPath.h"
#include "trace/NearAxis.h"

using namespace lenslab;
using lenslab::test::buildRows;
using lenslab::test::row;
using lenslab::test::stopRow;

namespace {

std::vector<std::string> bundledLenses() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(LENSLAB_SOURCE_DIR "/lenses"))
        if (isLensFileName(e.path().string())) out.push_back(e.path().string());
    return out;
}

// A paraxial ray on the designer's axis s = -z: height y, slope u = dy/ds, signed index n (negative
// while the light runs toward -s, after an odd number of reflections).
struct GlobalRay {
    double s, y, u, n;
};

// Meets a surface at sCurve (curvature c along +s) leaving into signed index nAfter: refraction and
// reflection are both n'u' = nu - y (n' - n) c.
void meet(GlobalRay& r, double sSurface, double c, double nAfter) {
    r.y += (sSurface - r.s) * r.u;
    r.s = sSurface;
    const double nu = r.n * r.u - r.y * (nAfter - r.n) * c;
    r.n = nAfter;
    r.u = nu / r.n;
}

// Surface k met by the ray, the light leaving into the medium of index `far` on its other side
// (the sign of n keeps the direction), or reflected (n' = -n) at a mirror.
void meetSurface(GlobalRay& r, const Surface& k, double far, bool reflect = false) {
    meet(r, -k.z, k.vertexCurvature(), reflect || k.mirror ? -r.n : std::copysign(far, r.n));
}

GlobalRay traceDirectGlobally(const LensSystem& lens, GlobalRay r) {
    for (const Surface& k : lens.surfaces) meetSurface(r, k, k.indexAfter);
    return r;
}

// The ghost reflecting at surface i, then j, traced from the original surfaces (no unfolded lens).
GlobalRay traceGhostGlobally(const LensSystem& lens, int i, int j, GlobalRay r) {
    const auto& s = lens.surfaces;
    for (int k = 0; k < i; ++k) meetSurface(r, s[k], s[k].indexAfter);
    meetSurface(r, s[i], 0, true);
    for (int k = i - 1; k > j; --k) meetSurface(r, s[k], lens.indexBefore(k));
    meetSurface(r, s[j], 0, true);
    for (int k = j + 1; k < int(s.size()); ++k) meetSurface(r, s[k], s[k].indexAfter);
    return r;
}

int countReflectingSurfaces(const LensSystem& lens) {
    int n = 0;
    for (std::size_t k = 0; k < lens.surfaces.size(); ++k) {
        const double before = k == 0 ? 1.0 : lens.surfaces[k - 1].indexAfter;
        n += !lens.surfaces[k].isStop && !lens.surfaces[k].mirror && before != lens.surfaces[k].indexAfter;
    }
    return n;
}

}  // namespace

// dgauss.50mm, read row by row: rows 1-5 and 7-11 change the index (eight between air and glass,
// rows 4 and 8 cemented), row 6 is the stop: 10 reflecting surfaces, 45 ghosts.
TEST(GhostPaths, CountIsNChooseTwoForEveryBundledLens) {
    const LensSystem dgauss = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat");
    EXPECT_EQ(countReflectingSurfaces(dgauss), 10);
    EXPECT_EQ(ghostPaths(dgauss).size(), 45u);
    for (const std::string& file : bundledLenses()) {
        const LensSystem lens = loadLensSystem(file);
        const int n = countReflectingSurfaces(lens);
        const std::vector<GhostPath> paths = ghostPaths(lens);
        EXPECT_EQ(int(paths.size()), n * (n - 1) / 2) << file;
        for (const GhostPath& p : paths) {
            EXPECT_LT(p.second, p.first) << file;
            EXPECT_FALSE(lens.surfaces[p.first].isStop) << file;
        }
        EXPECT_EQ(analyzeGhosts(analyzeLens(lens, std::nullopt, INFINITY)).ghosts.size(), paths.size()) << file;
    }
}

// A render cancelled while it picks its brightest ghosts: the analysis stops between two ghosts,
// so a set flag leaves none done; unset, all 45 of dgauss.50mm.
TEST(GhostAnalysis, AStopFlagEndsTheWorkBetweenTwoGhosts) {
    const LensAnalysis a = analyzeLens(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat"), std::nullopt, INFINITY);
    std::atomic<bool> stop{false};
    EXPECT_EQ(analyzeGhosts(a, &stop).ghosts.size(), 45u);
    stop = true;
    EXPECT_TRUE(analyzeGhosts(a, &stop).ghosts.empty());
}

// Every ghost of every bundled lens (aspheres, the reflex lens's mirrors included): its paraxial
// focus and the size of its image of a distant field against the global-axis trace above.
TEST(GhostAnalysis, ParaxialFocusMatchesAnIndependentTrace) {
    int checked = 0;
    for (const std::string& file : bundledLenses()) {
        const LensAnalysis a = analyzeLens(loadLensSystem(file), std::nullopt, INFINITY);
        const GhostAnalysis ghosts = analyzeGhosts(a);
        const double sDirect = -a.pupils.entrance.z;
        const GlobalRay chiefDirect = traceDirectGlobally(a.lens, {sDirect, 0, 1, 1});
        const double directHeight = chiefDirect.y + (-ghosts.filmZ - chiefDirect.s) * chiefDirect.u;
        for (const GhostImage& g : ghosts.ghosts) {
            const GlobalRay marginal = traceGhostGlobally(a.lens, g.path.first, g.path.second, {sDirect, 1, 0, 1});
            const double focusZ = -(marginal.s - marginal.y / marginal.u);
            EXPECT_NEAR(g.focusZ, focusZ, 1e-7 * std::max(1.0, std::fabs(focusZ)))
                << file << " ghost " << g.path.first + 1 << "-" << g.path.second + 1;
            EXPECT_NEAR(g.focusFromFilm, focusZ - ghosts.filmZ, 1e-7 * std::max(1.0, std::fabs(focusZ)));
            const GlobalRay chief = traceGhostGlobally(a.lens, g.path.first, g.path.second, {sDirect, 0, 1, 1});
            const double height = chief.y + (-ghosts.filmZ - chief.s) * chief.u;
            EXPECT_NEAR(g.fieldScale, height / directHeight, 1e-9 * std::max(1.0, std::fabs(g.fieldScale))) << file;
            EXPECT_EQ(g.focused, g.blurDiameter < kFocusedGhostDiameterMm);
            ++checked;
        }
        for (std::size_t k = 1; k < ghosts.ghosts.size(); ++k)
            EXPECT_GE(ghosts.ghosts[k - 1].relativeIntensity, ghosts.ghosts[k].relativeIntensity);
    }
    EXPECT_GT(checked, 300);
}

// An uncoated biconvex lens (R 50, -50, 5 mm of n 1.5): its one ghost reflects inside the glass at
// the rear face, then at the front face, and leaves. Gauss's equation n'/s' - n/s = (n' - n)/R at
// each surface in turn (n' = -n at a reflection) places its image 3.148 mm behind the rear vertex;
// the exact trace of near-axis rays through the unfolded ghost must land there, and it carries R^2
// of the direct light (both reflections bare, the two passes the direct image's own).
TEST(GhostAnalysis, BiconvexLensGhostAgainstGaussSurfaceBySurface) {
    std::vector<LensTableRow> rows = {stopRow(1, 30), row(50, 5, 1.5, 30), row(-50, 40, 1, 30)};
    rows[1].coating = rows[2].coating = "none";
    const LensSystem lens = buildRows(rows);
    ASSERT_EQ(ghostPaths(lens).size(), 1u);
    const double n = 1.5, r1 = 50, r2 = -50, d = 5;
    // s measured from each surface along the light's first direction.
    const double afterFront = n * r1 / (n - 1);                     // refraction at the front: image 150 behind it
    const double atRear = afterFront - d;                          // object for the rear face's reflection
    const double afterRear = 1 / (2 / r2 - 1 / atRear);            // 1/s' + 1/s = 2/R
    const double atFront = afterRear + d;                          // back to the front face
    const double afterSecond = 1 / (2 / r1 - 1 / atFront);         // reflected inside the front face
    const double atExit = afterSecond - d;                         // object for refraction out of the rear
    const double image = 1 / (n / atExit + (1 - n) / r2);          // n'/s' = n/s + (n' - n)/R, n' = 1
    EXPECT_NEAR(image, 3.148, 5e-4);
    const double zRear = lens.surfaces[2].z, expectedZ = zRear - image;

    const UnfoldedGhost g = unfoldGhost(lens, ghostPaths(lens).front());
    ASSERT_EQ(g.lens.surfaces.size(), 5u);  // stop, front, rear as mirror, front as mirror, rear
    const double h = nearAxisHeight(lens);
    const double exactZ = paraxialLimit(
        [&](double y) {
            return axisCrossingZ(traceNearAxis(g.lens, {{0, y, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm));
        },
        h);
    EXPECT_NEAR(exactZ, expectedZ, 1e-7);

    const GhostAnalysis analysis = analyzeGhosts(analyzeLens(lens, std::nullopt, INFINITY));
    ASSERT_EQ(analysis.ghosts.size(), 1u);
    EXPECT_NEAR(analysis.ghosts[0].focusZ, expectedZ, 1e-9);
    const double bare = std::pow((n - 1) / (n + 1), 2);
    EXPECT_NEAR(analysis.ghosts[0].reflectanceFirst, bare, 1e-15);
    EXPECT_NEAR(analysis.ghosts[0].energy, bare * bare, 1e-12);
}

// Two bare singlets, wide against a small stop (nothing vignettes): the ghost between the first and
// the last surface passes surfaces 2 and 3 three times and 1 and 4 once, against the direct image's
// once each, so it carries R1 R4 (T2 T3)^2 of the direct light: 0.04^2 0.96^4 at n 1.5.
TEST(GhostAnalysis, EnergyCountsEveryPassBetweenTheReflections) {
    std::vector<LensTableRow> rows = {stopRow(2, 5), row(100, 6, 1.5, 40), row(-100, 10, 1, 40), row(100, 6, 1.5, 40),
                                      row(-100, 60, 1, 40)};
    for (LensTableRow& r : rows) r.coating = r.stop ? "" : "none";
    const LensSystem lens = buildRows(rows);
    const GhostAnalysis analysis = analyzeGhosts(analyzeLens(lens, std::nullopt, INFINITY));
    ASSERT_EQ(analysis.ghosts.size(), 6u);
    const double R = 0.04, T = 0.96;
    bool found = false;
    for (const GhostImage& g : analysis.ghosts) {
        if (g.path.first != 4 || g.path.second != 1) continue;
        found = true;
        EXPECT_NEAR(g.energy, R * R * std::pow(T, 4), 1e-12);
    }
    EXPECT_TRUE(found);
}

TEST(GhostPaths, RefusesPathsThatAreNotGhosts) {
    const LensSystem lens = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat");
    EXPECT_THROW(unfoldGhost(lens, {2, 2}), OpticsError);
    EXPECT_THROW(unfoldGhost(lens, {11, 3}), OpticsError);
    EXPECT_THROW(unfoldGhost(lens, {3, -1}), OpticsError);
}
