#include "shapes/NurbsSurface.h"

#include <algorithm>

namespace lenslab {

namespace {

constexpr int kDice = 30;  // pbrt-v3's grid

struct Homogeneous {
    double x = 0, y = 0, z = 0, w = 0;
};
Homogeneous operator*(double s, const Homogeneous& a) { return {s * a.x, s * a.y, s * a.z, s * a.w}; }
Homogeneous& operator+=(Homogeneous& a, const Homogeneous& b) {
    a.x += b.x, a.y += b.y, a.z += b.z, a.w += b.w;
    return a;
}

// One parametric direction: its knots and order (degree + 1).
struct BasisAxis {
    std::vector<double> knots;
    int order = 0, count = 0;

    // The `order` non-zero basis functions at t and their derivatives, starting at index `first`
    // (Cox-de Boor, in the triangular form of Piegl and Tiller's "The NURBS Book", A2.2/A2.3).
    void evaluate(double t, int& first, std::vector<double>& value, std::vector<double>& derivative) const {
        const int p = order - 1;
        int span = p;
        while (span < count - 1 && t >= knots[span + 1]) ++span;
        first = span - p;
        std::vector<std::vector<double>> n(order, std::vector<double>(order, 0.0));  // n[degree][i]
        n[0][0] = 1;
        std::vector<double> left(order), right(order);
        for (int j = 1; j <= p; ++j) {
            left[j] = t - knots[span + 1 - j];
            right[j] = knots[span + j] - t;
            double saved = 0;
            for (int r = 0; r < j; ++r) {
                const double denom = right[r + 1] + left[j - r];
                const double temp = denom != 0 ? n[j - 1][r] / denom : 0;
                n[j][r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            n[j][j] = saved;
        }
        value = n[p];
        derivative.assign(order, 0.0);
        if (p == 0) return;
        // Derivative from the degree p-1 functions: p (N_{i,p-1} / (k_{i+p} - k_i) - N_{i+1,p-1} / (k_{i+p+1} - k_{i+1})).
        for (int r = 0; r <= p; ++r) {
            const int i = first + r;
            const double a = r > 0 ? n[p - 1][r - 1] : 0, b = r < p ? n[p - 1][r] : 0;
            const double da = knots[i + p] - knots[i], db = knots[i + p + 1] - knots[i + 1];
            derivative[r] = p * ((da != 0 ? a / da : 0) - (db != 0 ? b / db : 0));
        }
    }
};

BasisAxis readAxis(const ParamSet& p, const char* countName, const char* orderName, const char* knotsName) {
    BasisAxis a;
    a.count = p.getInt(countName, 0);
    a.order = p.getInt(orderName, 0);
    a.knots = p.getFloats(knotsName);
    if (a.order < 1 || a.order > 16) p.fail(std::string(orderName) + " must lie in [1, 16]");
    if (a.count < a.order) p.fail(std::string(countName) + " must be at least " + orderName);
    if (int(a.knots.size()) != a.count + a.order)
        p.fail(std::string(knotsName) + " needs " + countName + " + " + orderName + " = " + std::to_string(a.count + a.order) +
               " values, got " + std::to_string(a.knots.size()));
    for (std::size_t i = 1; i < a.knots.size(); ++i)
        if (a.knots[i] < a.knots[i - 1]) p.fail(std::string(knotsName) + " must not decrease");
    return a;
}

}  // namespace

MeshData diceNurbs(const ParamSet& p) {
    const BasisAxis U = readAxis(p, "nu", "uorder", "uknots"), V = readAxis(p, "nv", "vorder", "vknots");
    const double u0 = p.getFloat("u0", U.knots[U.order - 1]), u1 = p.getFloat("u1", U.knots[U.count]);
    const double v0 = p.getFloat("v0", V.knots[V.order - 1]), v1 = p.getFloat("v1", V.knots[V.count]);
    if (!(u0 < u1 && v0 < v1)) p.fail("needs u0 < u1 and v0 < v1");
    const std::size_t points = std::size_t(U.count) * V.count;
    std::vector<Homogeneous> cp;
    if (p.has("Pw")) {
        const std::vector<double> pw = p.getFloats("Pw");
        if (pw.size() != 4 * points) p.fail("\"Pw\" needs 4 values for each of nu x nv points");
        for (std::size_t i = 0; i < points; ++i) {
            const double w = pw[4 * i + 3];
            if (!(w > 0)) p.fail("\"Pw\" weights must be positive");
            cp.push_back({pw[4 * i], pw[4 * i + 1], pw[4 * i + 2], w});  // given already multiplied by w, as pbrt-v3 reads them
        }
    } else {
        const std::vector<Vec3f> P = p.getPoints("P");
        if (P.size() != points) p.fail("\"P\" needs nu x nv = " + std::to_string(points) + " points");
        for (const Vec3f& x : P) cp.push_back({x.x, x.y, x.z, 1});
    }

    MeshData m;
    std::vector<double> nu, du, nv, dv;
    for (int iv = 0; iv <= kDice; ++iv) {
        const double v = v0 + (v1 - v0) * iv / kDice;
        int fv;
        V.evaluate(v, fv, nv, dv);
        for (int iu = 0; iu <= kDice; ++iu) {
            const double u = u0 + (u1 - u0) * iu / kDice;
            int fu;
            U.evaluate(u, fu, nu, du);
            Homogeneous s, su, sv;
            for (int b = 0; b < V.order; ++b)
                for (int a = 0; a < U.order; ++a) {
                    const Homogeneous& c = cp[std::size_t(fv + b) * U.count + (fu + a)];
                    s += (nu[a] * nv[b]) * c;
                    su += (du[a] * nv[b]) * c;
                    sv += (nu[a] * dv[b]) * c;
                }
            // The rational surface S = A / w and its partials (A_u - w_u S) / w.
            const Vec3f point{float(s.x / s.w), float(s.y / s.w), float(s.z / s.w)};
            const Vec3f dpdu{float((su.x - su.w * point.x) / s.w), float((su.y - su.w * point.y) / s.w),
                             float((su.z - su.w * point.z) / s.w)};
            const Vec3f dpdv{float((sv.x - sv.w * point.x) / s.w), float((sv.y - sv.w * point.y) / s.w),
                             float((sv.z - sv.w * point.z) / s.w)};
            m.p.push_back(point);
            const Vec3f n = cross(dpdu, dpdv);
            m.n.push_back(length(n) > 0 ? normalize(n) : Vec3f{0, 0, 1});
            m.uv.push_back(float(u));
            m.uv.push_back(float(v));
        }
    }
    const auto at = [](int iu, int iv) { return std::uint32_t(iv * (kDice + 1) + iu); };
    for (int iv = 0; iv < kDice; ++iv)
        for (int iu = 0; iu < kDice; ++iu)
            for (std::uint32_t i : {at(iu, iv), at(iu + 1, iv), at(iu + 1, iv + 1), at(iu, iv), at(iu + 1, iv + 1), at(iu, iv + 1)})
                m.indices.push_back(i);
    return m;
}

}  // namespace lenslab
