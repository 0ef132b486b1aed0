// Seidel sums (analysis/SeidelSums.h) against the same sums computed here from a y-nu trace written
// in the test (1e-9), and against what real rays do: a Cartesian singlet has no spherical aberration
// at any order (its conic's share cancels the sphere's), and a slow singlet's marginal ray misses
// the paraxial focus by S_I / (2 n' u'), u' its converging slope (the third-order transverse
// aberration: a positive lens, S_I > 0, sends it across the axis).
#include <gtest/gtest.h>

#include <cmath>

#include "PrescriptionRows.h"
#include "analysis/SeidelSums.h"
#include "firstorder/FirstOrder.h"
#include "trace/ExactTrace.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {


// The test's own sums for a lens of spheres at infinity: marginal ray at the stop's rim, chief ray
// through its centre at slope tan(field), both by the textbook recurrences.
SeidelTerms expectedTotal(const LensSystem& lens, double fieldDegrees, std::vector<SeidelTerms>* perSurface) {
    const int n = int(lens.surfaces.size());
    const auto trace = [&](double y, double u, std::vector<double>& ys, std::vector<double>& us) {
        for (int k = 0; k < n; ++k) {
            const double n0 = k == 0 ? 1.0 : lens.surfaces[k - 1].indexAfter, n1 = lens.surfaces[k].indexAfter;
            ys.push_back(y);
            us.push_back(u);
            u = (n0 * u - y * (n1 - n0) * lens.surfaces[k].curvature) / n1;
            if (k + 1 < n) y += (lens.surfaces[k].z - lens.surfaces[k + 1].z) * u;
        }
        us.push_back(u);
    };
    // Unit rays, then their multiples: the marginal ray's height at the stop is its radius; the chief
    // ray's is 0 there.
    std::vector<double> ya, ua, yb, ub;
    trace(1, 0, ya, ua);
    trace(0, 1, yb, ub);
    const int stop = lens.stopIndex;
    const double m = lens.stop().apertureRadius / ya[stop];
    const double t = std::tan(fieldDegrees * M_PI / 180), alpha = -t * yb[stop] / ya[stop];
    const double h = (alpha * ua[0] + t * ub[0]) * m * ya[0] - m * ua[0] * (alpha * ya[0] + t * yb[0]);
    SeidelTerms total;
    for (int k = 0; k < n; ++k) {
        const double n0 = k == 0 ? 1.0 : lens.surfaces[k - 1].indexAfter, n1 = lens.surfaces[k].indexAfter;
        const double c = lens.surfaces[k].curvature;
        const double y = m * ya[k], u = m * ua[k], uAfter = m * ua[k + 1];
        const double yc = alpha * ya[k] + t * yb[k], uc = alpha * ua[k] + t * ub[k];
        const double A = n0 * (u + y * c), Ac = n0 * (uc + yc * c), d = uAfter / n1 - u / n0;
        SeidelTerms s;
        s.spherical = -A * A * y * d;
        s.coma = -A * Ac * y * d;
        s.astigmatism = -Ac * Ac * y * d;
        s.petzval = -h * h * c * (1 / n1 - 1 / n0);
        s.distortion = Ac / A * (s.astigmatism + s.petzval);
        if (perSurface) perSurface->push_back(s);
        total.spherical += s.spherical, total.coma += s.coma, total.astigmatism += s.astigmatism;
        total.petzval += s.petzval, total.distortion += s.distortion;
    }
    return total;
}

void expectTerms(const SeidelTerms& a, const SeidelTerms& b, double scale, const std::string& what) {
    EXPECT_NEAR(a.spherical, b.spherical, 1e-9 * scale) << what;
    EXPECT_NEAR(a.coma, b.coma, 1e-9 * scale) << what;
    EXPECT_NEAR(a.astigmatism, b.astigmatism, 1e-9 * scale) << what;
    EXPECT_NEAR(a.petzval, b.petzval, 1e-9 * scale) << what;
    EXPECT_NEAR(a.distortion, b.distortion, 1e-9 * scale) << what;
}

}  // namespace

TEST(SeidelSums, EqualAYNuCalculationWrittenHereSurfaceBySurface) {
    for (const char* file : {"/lenses/dgauss.50mm.dat", "/lenses/design/cooke-triplet-50mm.zmx"}) {
        const LensSystem lens = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + file);
        const double field = 14;
        const std::optional<SeidelSums> s = seidelSums(lens, field, kInf);
        ASSERT_TRUE(s) << file;
        std::vector<SeidelTerms> expected;
        const SeidelTerms total = expectedTotal(lens, field, &expected);
        const double scale = std::max({std::fabs(total.spherical), std::fabs(total.coma), std::fabs(total.astigmatism),
                                       std::fabs(total.petzval), std::fabs(total.distortion)});
        ASSERT_GT(scale, 0);
        expectTerms(s->total, total, scale, file);
        ASSERT_EQ(s->surfaces.size(), expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k) expectTerms(s->surfaces[k], expected[k], scale, std::string(file) + " surface " + std::to_string(k + 1));
    }
}

TEST(SeidelSums, ACartesianSingletHasNoSphericalAberration) {
    const double n = 1.5;
    const LensSystem sphere = planoConvex(n, 100, 0), cartesian = planoConvex(n, 100, -n * n);
    const SeidelSums a = *seidelSums(sphere, 0, kInf), b = *seidelSums(cartesian, 0, kInf);
    ASSERT_GT(std::fabs(a.total.spherical), 1e-4);
    EXPECT_NEAR(b.total.spherical, 0, 1e-12 * std::fabs(a.total.spherical) + 1e-15);
}

TEST(SeidelSums, PredictASlowSinglesMarginalRayOnTheParaxialFocus) {
    // f 100 mm at f/20: fifth-order aberration is below a percent of the third.
    const LensSystem lens = buildRows({stopRow(1, 5), row(60, 3, 1.5, 12), row(-300, 0, 0, 12)});
    const SeidelSums s = *seidelSums(lens, 0, kInf);
    const FirstOrder fo = computeFirstOrder(lens);
    const TraceResult r = traceRay(lens, {{0, 2.5, 10}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    ASSERT_TRUE(r.ok());
    const double t = (fo.zFPrime - r.ray.origin.z) / r.ray.direction.z;
    const double transverse = r.ray.origin.y + t * r.ray.direction.y;
    // The marginal ray's image-space slope along +s (toward the film): -2.5 / f; n' = 1.
    const double uImage = -2.5 / fo.efl;
    EXPECT_GT(s.total.spherical, 0);
    EXPECT_LT(transverse, -1e-4);
    EXPECT_NEAR(transverse, s.total.spherical / (2 * uImage), 0.01 * std::fabs(transverse));
}
