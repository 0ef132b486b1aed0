// The surface forms beyond the even asphere: Forbes's Q-types against the closed forms printed in
// Forbes 2007 (Opt. Express 15, 5218), the odd asphere against its polynomial, every form's slope
// against its sag's derivative, and the trace landing on the sag.
#include <gtest/gtest.h>

#include <cmath>

#include "prescription/FormSag.h"
#include "prescription/LensSystem.h"
#include "trace/ExactTrace.h"
#include "PrescriptionRows.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {

SurfaceForm qForm(SurfaceKind kind, double norm, std::initializer_list<double> terms) {
    SurfaceForm f;
    f.kind = kind;
    f.normalisationRadius = norm;
    for (double t : terms) f.terms[f.termCount++] = t;
    return f;
}

double formSagOf(const SurfaceForm& f, double c, double k, double r, double* slope = nullptr) {
    double sag, g, u;
    formSag(FormConstants<double>::of(f), c, 1 + k, r * r, sag, g, u);
    if (slope) *slope = g * r;
    return sag;
}

double sphereSag(double c, double r) { return c * r * r / (1 + std::sqrt(1 - c * c * r * r)); }

// Forbes 2007, eq. (A.?) and section 2: the first Qbfs and Qcon polynomials written out.
double qbfs2(double x) { return std::sqrt(2.0 / 95) * (29 - 4 * x * (25 - 19 * x)); }
double qbfs3(double x) { return std::sqrt(2.0 / 2545) * (207 - 4 * x * (315 - x * (577 - 320 * x))); }
double qcon2(double x) { return 15 - 14 * x * (3 - 2 * x); }
double qcon3(double x) { return -(35 - 12 * x * (14 - x * (21 - 10 * x))); }

}  // namespace

TEST(SurfaceForms, QbfsWithOnlyItsBaseSphereIsThatSphere) {
    const double c = 1 / 35.0;
    const SurfaceForm f = qForm(SurfaceKind::Qbfs, 20, {0, 0, 0});
    for (double r : {0.0, 1.0, 7.5, 19.0, 30.0}) EXPECT_EQ(formSagOf(f, c, 0, r), sphereSag(c, r)) << r;
    // And a lens with such a surface traces as the sphere does, ray for ray.
    LensTableRow front = row(35, 5, 1.6, 30);
    front.stop = true;
    const LensSystem sphere = buildRows({front, row(-50, 40, 0, 30)}, "q");
    front.form = f;
    const LensSystem q = buildRows({front, row(-50, 40, 0, 30)}, "q");
    for (double y : {-12.0, -3.0, 0.5, 9.0}) {
        const Ray ray{{0.3, y, 10}, normalize({0, -0.02, -1})};
        const TraceResult a = traceRay(sphere, ray, TraceDirection::SceneToFilm);
        const TraceResult b = traceRay(q, ray, TraceDirection::SceneToFilm);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_NEAR(b.ray.origin.y, a.ray.origin.y, 1e-12);
        EXPECT_NEAR(b.ray.direction.y, a.ray.direction.y, 1e-13);
    }
}

TEST(SurfaceForms, SingleTermQbfsAgainstTheClosedForm) {
    const double c = -1 / 80.0, norm = 25;
    for (int m : {0, 1, 2, 3}) {
        SurfaceForm f = qForm(SurfaceKind::Qbfs, norm, {0, 0, 0, 0});
        f.terms[m] = 0.013;
        for (double r : {0.0, 5.0, 12.5, 21.0, 25.0}) {
            const double x = r * r / (norm * norm);
            const double q = m == 0 ? 1 : m == 1 ? (13 - 16 * x) / std::sqrt(19.0) : m == 2 ? qbfs2(x) : qbfs3(x);
            const double expected = sphereSag(c, r) + x * (1 - x) / std::sqrt(1 - c * c * r * r) * 0.013 * q;
            EXPECT_NEAR(formSagOf(f, c, 0, r), expected, 1e-15) << "m " << m << " r " << r;
        }
    }
}

TEST(SurfaceForms, SingleTermQconAgainstTheClosedForm) {
    const double c = 1 / 60.0, k = -0.7, norm = 30;
    for (int m : {0, 1, 2, 3}) {
        SurfaceForm f = qForm(SurfaceKind::Qcon, norm, {0, 0, 0, 0});
        f.terms[m] = -0.21;
        for (double r : {0.0, 6.0, 18.0, 29.0}) {
            const double x = r * r / (norm * norm);
            const double q = m == 0 ? 1 : m == 1 ? -(5 - 6 * x) : m == 2 ? qcon2(x) : qcon3(x);
            const double conic = c * r * r / (1 + std::sqrt(1 - (1 + k) * c * c * r * r));
            EXPECT_NEAR(formSagOf(f, c, k, r), conic + x * x * -0.21 * q, 1e-14) << "m " << m << " r " << r;
        }
    }
}

TEST(SurfaceForms, OddAsphereIsItsPolynomial) {
    SurfaceForm f;
    f.kind = SurfaceKind::OddAsphere;
    f.terms[0] = 1e-3, f.terms[2] = -2e-5, f.terms[4] = 3e-8;  // r, r^3, r^5
    f.termCount = 5;
    const double c = 1 / 45.0;
    for (double r : {0.0, 2.0, 9.0, 14.0})
        EXPECT_NEAR(formSagOf(f, c, 0, r), sphereSag(c, r) + 1e-3 * r - 2e-5 * r * r * r + 3e-8 * std::pow(r, 5), 1e-15);
}

// g r is the sag's derivative: every form's slope against a central difference of its sag.
TEST(SurfaceForms, SlopesAreTheSagsDerivative) {
    SurfaceForm odd;
    odd.kind = SurfaceKind::OddAsphere;
    odd.terms = {2e-3, 1e-4, -3e-5, 2e-7};
    odd.termCount = 4;
    for (const SurfaceForm& f : {qForm(SurfaceKind::Qbfs, 22, {0.02, -0.01, 0.004, 0.002, -0.001}),
                                 qForm(SurfaceKind::Qcon, 22, {0.03, -0.01, 0.005, -0.002, 0.001, 0.0005}), odd}) {
        for (double r : {1.0, 6.0, 13.0, 20.0}) {
            double slope;
            formSagOf(f, 1 / 50.0, 0, r, &slope);
            const double h = 1e-5;
            const double numeric = (formSagOf(f, 1 / 50.0, 0, r + h) - formSagOf(f, 1 / 50.0, 0, r - h)) / (2 * h);
            EXPECT_NEAR(slope, numeric, 1e-8) << surfaceKindName(f.kind) << " r " << r;
        }
    }
}

// A ray traced onto a Qcon surface lands on it: its hit satisfies z = vertex - sag(r) in the
// surface's frame, and refracts about the sag's normal (Snell's law holds across it).
TEST(SurfaceForms, TraceLandsOnTheQconSag) {
    LensTableRow front = row(40, 6, 1.7, 36);
    front.stop = true;
    front.conic = -0.6;
    front.form = qForm(SurfaceKind::Qcon, 18, {-0.08, 0.03, -0.01});
    const LensSystem lens = buildRows({front, row(-70, 40, 0, 36)}, "qcon");
    const Surface& s = lens.surfaces[0];
    TraceOptions one;
    one.end = 1;
    for (double y : {-15.0, -7.0, 0.0, 4.0, 16.0}) {
        const Ray ray{{1.5, y, 10}, normalize({0.01, 0.03, -1})};
        const TraceResult r = traceRay(lens, ray, TraceDirection::SceneToFilm, one);
        ASSERT_TRUE(r.ok()) << y;
        const double h = std::hypot(r.ray.origin.x, r.ray.origin.y);
        EXPECT_NEAR(r.ray.origin.z, s.z - sag(s, h), 1e-12) << y;
        // Snell: n sin i = n' sin i' about the normal (g x, g y, 1).
        double slope;
        formSagOf(s.form, s.curvature, s.conic, h, &slope);
        const double g = h > 0 ? slope / h : 0;
        const Vec3 normal = normalize({g * r.ray.origin.x, g * r.ray.origin.y, 1});
        auto sine = [&](const Vec3& d) {
            const double c = dot(d, normal);
            return std::sqrt(std::max(0.0, 1 - c * c));
        };
        EXPECT_NEAR(sine(ray.direction), 1.7 * sine(r.ray.direction), 1e-12) << y;
    }
    // The paraxial power sees the base curvature only: Qcon starts at r^4.
    EXPECT_EQ(s.vertexCurvature(), s.curvature);
}
