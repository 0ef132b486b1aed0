#pragma once
// The sag of the surface forms beyond the even asphere, and its slope, written once on plain scalars
// for the prescription (float or double) and the tracer alike. Every form here is a function of the
// squared height rho = x^2 + y^2 about the vertex:
//   odd asphere  conic(rho) + sum_i b_i r^i                                  (Zemax ODDASPH)
//   Qbfs         sphere(rho) + x (1 - x) / sqrt(1 - c^2 rho) sum_m a_m Qbfs_m(x)   x = rho / r_norm^2
//   Qcon         conic(rho) + x^2 sum_m a_m Qcon_m(x)
// (G. W. Forbes, "Shape specification for axially symmetric optical surfaces", Opt. Express 15,
// 5218 (2007); the Qbfs recurrence of Forbes, "Robust, efficient computational methods for
// axially symmetric optical aspheres", Opt. Express 18, 19700 (2010), appendix A). Qcon_m(x) is
// the Jacobi polynomial P_m^(0,4)(2x - 1).
#include <array>
#include <cmath>
#include <limits>

#include "prescription/SurfaceForm.h"

namespace lenslab {

// Forbes 2010 (A.14-A.16): the Qbfs recurrence's constants f_m, g_m, h_m for m < kFormTerms.
struct QbfsRecurrence {
    std::array<double, kFormTerms> f{}, g{}, h{};
};
const QbfsRecurrence& qbfsRecurrence();

template <class T>
struct FormConstants {
    SurfaceKind kind = SurfaceKind::EvenAsphere;
    int count = 0;                // terms used
    T terms[kFormTerms] = {};
    T invNorm2 = 0;               // 1 / r_norm^2 (Q-types)
    T f[kFormTerms] = {}, g[kFormTerms] = {}, h[kFormTerms] = {};  // Qbfs recurrence

    static FormConstants of(const SurfaceForm& form) {
        FormConstants c;
        c.kind = form.kind;
        c.count = form.termCount;
        for (int i = 0; i < form.termCount; ++i) c.terms[i] = T(form.terms[i]);
        if (form.normalisationRadius > 0) c.invNorm2 = T(1 / (form.normalisationRadius * form.normalisationRadius));
        if (form.kind == SurfaceKind::Qbfs) {
            const QbfsRecurrence& r = qbfsRecurrence();
            for (int m = 0; m < kFormTerms; ++m) {
                c.f[m] = T(r.f[m]);
                c.g[m] = T(r.g[m]);
                c.h[m] = T(r.h[m]);
            }
        }
        return c;
    }
};

// sum_m a_m Q_m(x) and its derivative in x, for the Q-types.
template <class T>
inline void qSum(const FormConstants<T>& fc, T x, T& sum, T& slope) {
    sum = 0;
    slope = 0;
    if (fc.kind == SurfaceKind::Qcon) {
        // Jacobi P_n^(0,4)(t), t = 2x - 1: 2n(n+4)(2n+2) P_n = (2n+3)((2n+4)(2n+2) t - 16) P_{n-1}
        // - 2(n-1)(n+3)(2n+4) P_{n-2}; differentiated alongside (dt/dx = 2).
        const T t = T(2) * x - T(1);
        T p2 = 0, p1 = 0, d2 = 0, d1 = 0;  // P_{n-2}, P_{n-1} and their t-derivatives
        for (int n = 0; n < fc.count; ++n) {
            T p, d;
            if (n == 0) {
                p = 1;
                d = 0;
            } else if (n == 1) {
                p = T(3) * t - T(2);
                d = 3;
            } else {
                const T a = T(2 * n + 3), b = T((2 * n + 4) * (2 * n + 2)), e = T(2 * (n - 1) * (n + 3) * (2 * n + 4));
                const T den = T(2 * n * (n + 4) * (2 * n + 2));
                p = (a * (b * t - T(16)) * p1 - e * p2) / den;
                d = (a * ((b * t - T(16)) * d1 + b * p1) - e * d2) / den;
            }
            sum += fc.terms[n] * p;
            slope += fc.terms[n] * T(2) * d;
            p2 = p1;
            p1 = p;
            d2 = d1;
            d1 = d;
        }
        return;
    }
    // Qbfs: P_0 = 2, P_1 = 6 - 8x, P_m = (2 - 4x) P_{m-1} - P_{m-2}; Q_0 = 1, Q_1 = (13 - 16x) / sqrt 19,
    // Q_m = (P_m - g_{m-1} Q_{m-1} - h_{m-2} Q_{m-2}) / f_m.
    T pm2 = 0, pm1 = 0, qm2 = 0, qm1 = 0, dpm2 = 0, dpm1 = 0, dqm2 = 0, dqm1 = 0;
    for (int m = 0; m < fc.count; ++m) {
        T p, dp, q, dq;
        if (m == 0) {
            p = 2;
            dp = 0;
            q = 1;
            dq = 0;
        } else if (m == 1) {
            p = T(6) - T(8) * x;
            dp = -8;
            q = (T(13) - T(16) * x) / std::sqrt(T(19));
            dq = T(-16) / std::sqrt(T(19));
        } else {
            p = (T(2) - T(4) * x) * pm1 - pm2;
            dp = T(-4) * pm1 + (T(2) - T(4) * x) * dpm1 - dpm2;
            q = (p - fc.g[m - 1] * qm1 - fc.h[m - 2] * qm2) / fc.f[m];
            dq = (dp - fc.g[m - 1] * dqm1 - fc.h[m - 2] * dqm2) / fc.f[m];
        }
        sum += fc.terms[m] * q;
        slope += fc.terms[m] * dq;
        pm2 = pm1;
        pm1 = p;
        dpm2 = dpm1;
        dpm1 = dp;
        qm2 = qm1;
        qm1 = q;
        dqm2 = dqm1;
        dqm1 = dq;
    }
}

// The form at squared height rho on a base of curvature c and conic factor K = 1 + k: its sag, g =
// sag'(r) / r (the gradient is (g x, g y, 1)), and u = 1 - K c^2 rho, which must stay >= 0.
template <class T>
inline void formSag(const FormConstants<T>& fc, T c, T K, T rho, T& sag, T& g, T& u) {
    u = T(1) - K * c * c * rho;
    const T root = std::sqrt(u > T(0) ? u : T(0));
    const T tiny = std::numeric_limits<T>::min();
    sag = c * rho / (T(1) + root);
    g = c / (root > T(0) ? root : tiny);
    if (fc.kind == SurfaceKind::OddAsphere) {
        const T r = std::sqrt(rho);
        T poly = 0, slope = 0;  // sum b_i r^i and sum i b_i r^(i-1)
        for (int i = fc.count; i >= 1; --i) {
            poly = poly * r + fc.terms[i - 1];
            slope = slope * r + T(i) * fc.terms[i - 1];
        }
        sag += poly * r;
        g += slope / (r > T(0) ? r : tiny);
        return;
    }
    if (fc.kind == SurfaceKind::EvenAsphere || fc.count == 0) return;
    const T x = rho * fc.invNorm2;
    T sum, sumSlope;
    qSum(fc, x, sum, sumSlope);
    if (fc.kind == SurfaceKind::Qcon) {
        sag += x * x * sum;
        g += T(2) * fc.invNorm2 * (T(2) * x * sum + x * x * sumSlope);
        return;
    }
    // Qbfs on its sphere: phi = 1 / sqrt(1 - c^2 rho), d(phi)/dr = c^2 r phi^3.
    const T v = T(1) - c * c * rho;
    const T phi = T(1) / std::sqrt(v > T(0) ? v : tiny);
    const T w = x * (T(1) - x);
    sag += w * phi * sum;
    g += T(2) * fc.invNorm2 * phi * ((T(1) - T(2) * x) * sum + w * sumSlope) + w * sum * c * c * phi * phi * phi;
}

// The toroid at (x, y): the y-z profile z(y) turned about the axis x = 0, z = R (FormSagOf's other
// case): sag = R - s sqrt((R - z(y))^2 - x^2), s the sign of R, and its gradient; u < 0 where the
// profile or the turned circle is undefined.
template <class T>
inline void toroidSag(const FormConstants<T>& fc, T c, T K, T x, T y, T& sag, T& gx, T& gy, T& u) {
    const T rho = y * y;
    u = T(1) - K * c * c * rho;
    const T root = std::sqrt(u > T(0) ? u : T(0));
    T poly = 0, slope = 0;  // sum a_i y^(2i) / y^2 and its derivative / y
    for (int i = fc.count - 1; i >= 1; --i) {
        poly = poly * rho + fc.terms[i];
        slope = slope * rho + T(2 * i) * fc.terms[i];
    }
    const T zy = c * rho / (T(1) + root) + poly * rho;
    const T dzy = y * (c / (root > T(0) ? root : std::numeric_limits<T>::min()) + slope);
    const T radius = fc.terms[0];
    if (radius == T(0)) {
        sag = zy, gx = 0, gy = dzy;
        return;
    }
    const T a = radius - zy, w2 = a * a - x * x;
    const T w = std::sqrt(w2 > T(0) ? w2 : T(0));
    const T sign = radius > T(0) ? T(1) : T(-1);
    u = w2 < T(0) ? w2 : u;
    sag = radius - sign * w;
    const T inverse = T(1) / (w > T(0) ? w : std::numeric_limits<T>::min());
    gx = sign * x * inverse;
    gy = sign * a * dzy * inverse;
}

}  // namespace lenslab
