#include "prescription/Medium.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "prescription/LensTable.h"
#include "prescription/NumberText.h"

namespace lenslab {
namespace {

double squaredMicrometres(double wavelengthNm) { return (wavelengthNm * 1e-3) * (wavelengthNm * 1e-3); }

// A natural cubic spline through the table (nm ascending), held at its ends.
double tableIndex(const std::vector<std::array<double, 2>>& t, double nm) {
    const std::size_t n = t.size();
    if (nm <= t.front()[0]) return t.front()[1];
    if (nm >= t.back()[0]) return t.back()[1];
    // Second derivatives by the tridiagonal solve (zero at both ends).
    std::vector<double> second(n, 0.0), u(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double h0 = t[i][0] - t[i - 1][0], h1 = t[i + 1][0] - t[i][0];
        const double sig = h0 / (h0 + h1);
        const double p = sig * second[i - 1] + 2;
        second[i] = (sig - 1) / p;
        const double slopes = (t[i + 1][1] - t[i][1]) / h1 - (t[i][1] - t[i - 1][1]) / h0;
        u[i] = (6 * slopes / (h0 + h1) - sig * u[i - 1]) / p;
    }
    for (std::size_t k = n - 1; k-- > 1;) second[k] = second[k] * second[k + 1] + u[k];
    std::size_t hi = 1;
    while (t[hi][0] < nm) ++hi;
    const std::size_t lo = hi - 1;
    const double h = t[hi][0] - t[lo][0];
    const double a = (t[hi][0] - nm) / h, b = 1 - a;
    return a * t[lo][1] + b * t[hi][1] + ((a * a * a - a) * second[lo] + (b * b * b - b) * second[hi]) * h * h / 6;
}

// The formula as written, anywhere; NaN where it has no real value.
double formulaIndex(const Medium& m, double wavelengthNm) {
    const auto& c = m.coefficients;
    const double x = squaredMicrometres(wavelengthNm);
    switch (m.formula) {
    case DispersionFormula::Constant:
        return c[0];
    case DispersionFormula::Sellmeier: {
        double n2 = 1 + c[0];
        for (std::size_t i = 1; i + 1 < c.size(); i += 2) n2 += c[i] * x / (x - c[i + 1]);
        return std::sqrt(n2);
    }
    case DispersionFormula::SchottPolynomial: {
        const double y = 1 / x;
        const double inverse = y * (c[3] + y * (c[4] + y * (c[5] + y * (c[6] + y * (c[7] + y * c[8])))));
        return std::sqrt(c[0] + x * (c[1] + x * (c[2] + x * c[9])) + inverse);
    }
    case DispersionFormula::Herzberger: {
        const double m = 1 / (x - 0.028);
        return c[0] + m * (c[1] + m * c[2]) + x * (c[3] + x * (c[4] + x * c[5]));
    }
    case DispersionFormula::Conrady: {
        const double l = std::sqrt(x);
        return c[0] + c[1] / l + c[2] / std::pow(l, 3.5);
    }
    case DispersionFormula::SellmeierTwo:
        return std::sqrt(1 + c[0] + c[1] * x / (x - c[2] * c[2]) + c[3] / (x - c[4] * c[4]));
    case DispersionFormula::HandbookOne: return std::sqrt(c[0] + c[1] / (x - c[2]) - c[3] * x);
    case DispersionFormula::HandbookTwo: return std::sqrt(c[0] + c[1] * x / (x - c[2]) - c[3] * x);
    case DispersionFormula::Tabulated: return tableIndex(m.table, wavelengthNm);
    }
    return c[0];
}

bool physical(double n) { return std::isfinite(n) && n >= 1; }

// The model glass n^2 = 1 + B x / (x - C), x = L^2 (Sellmeier 1871, one absorption line at
// L = sqrt(C) in the ultraviolet), with B fixed by n(d) = nd for each pole C:
//   B(C) = (nd^2 - 1) (xd - C) / xd,   n(L)^2 = 1 + (nd^2 - 1) r_L(C),   r_L(C) = x (xd - C) / (xd (x - C)).
// For 0 <= C < xF (< xd < xC): d r_F/dC = xF (xd - xF) / (xd (xF - C)^2) > 0 and
// d r_C/dC = xC (xd - xC) / (xd (xC - C)^2) < 0, so nF - nC rises strictly and continuously from 0
// at C = 0 (no dispersion) to infinity as C -> xF. Every nd > 1, Vd > 0 therefore has exactly
// one C in (0, xF), found by bisection; B > 0, and dn^2/dx = -B C / (x - C)^2 < 0: the index falls
// with wavelength everywhere above the pole. For nd 1.3-2.1 and Vd 15-100 the pole lies at
// 76-202 nm, below the 360 nm that renders use.
Medium solveModelGlass(double nd, double vd) {
    const double xd = squaredMicrometres(kWavelengthD);
    const double dispersion = (nd - 1) / vd;  // nF - nC
    Medium m;
    m.formula = DispersionFormula::Sellmeier;
    auto withPole = [&](double c) {
        m.coefficients[1] = (nd * nd - 1) * (xd - c) / xd;
        m.coefficients[2] = c;
        return refractiveIndex(m, kWavelengthF) - refractiveIndex(m, kWavelengthC) - dispersion;
    };
    double low = 0, high = squaredMicrometres(kWavelengthF);
    for (;;) {  // until low and high are neighbouring doubles
        const double mid = low + (high - low) / 2;
        if (!(low < mid && mid < high)) break;
        if (withPole(mid) < 0) low = mid;
        else high = mid;
    }
    withPole(std::fabs(withPole(low)) < std::fabs(withPole(high)) ? low : high);
    return m;
}

}  // namespace

Medium air() {
    Medium m = constantIndex(1);
    m.name = "air";
    return m;
}

Medium constantIndex(double n) {
    if (!(std::isfinite(n) && n > 0))
        throw std::invalid_argument("refractive index " + formatNumber(n) + " is not finite and positive");
    Medium m;
    m.coefficients[0] = n;
    m.nd = n;
    return m;
}

Medium modelGlass(double nd, double vd) {
    if (!(std::isfinite(nd) && nd > 1 && std::isfinite(vd) && vd > 0))
        throw std::invalid_argument("no model glass for nd " + formatNumber(nd) + ", Vd " + formatNumber(vd) +
                                    ": nd must exceed 1 and Vd be positive");
    Medium m = solveModelGlass(nd, vd);
    m.name = "model " + formatNumber(nd) + "/" + formatNumber(vd);
    m.nd = nd;
    m.vd = vd;
    return m;
}

double refractiveIndex(const Medium& m, double wavelengthNm) {
    if (!(std::isfinite(wavelengthNm) && wavelengthNm > 0))
        throw std::invalid_argument("wavelength " + formatNumber(wavelengthNm) + " nm is not finite and positive");
    const double n = formulaIndex(m, wavelengthNm);
    if (m.formula == DispersionFormula::Constant || physical(n)) return n;
    if (m.maxNm > m.minNm) {
        const double held = formulaIndex(m, std::clamp(wavelengthNm, m.minNm, m.maxNm));
        if (physical(held)) return held;
    }
    return m.nd;
}

Medium tabulatedMedium(const std::string& name, std::vector<std::array<double, 2>> pairs) {
    if (pairs.size() < 2) throw std::invalid_argument(name + ": a table of indices needs at least two wavelengths");
    for (const auto& p : pairs)
        if (!(std::isfinite(p[0]) && p[0] > 0 && std::isfinite(p[1]) && p[1] > 0))
            throw std::invalid_argument(name + ": wavelength " + formatNumber(p[0]) + " nm, index " + formatNumber(p[1]) +
                                        " is not a finite positive pair");
    std::sort(pairs.begin(), pairs.end());
    for (std::size_t i = 1; i < pairs.size(); ++i)
        if (pairs[i][0] == pairs[i - 1][0])
            throw std::invalid_argument(name + ": wavelength " + formatNumber(pairs[i][0]) + " nm is listed twice");
    Medium m;
    m.name = name;
    m.formula = DispersionFormula::Tabulated;
    m.table = std::move(pairs);
    m.minNm = m.table.front()[0];
    m.maxNm = m.table.back()[0];
    m.nd = refractiveIndex(m, kWavelengthD);
    m.vd = abbeNumber(m);
    return m;
}

bool isDispersive(const Medium& m) {
    if (m.formula == DispersionFormula::Tabulated)
        return std::any_of(m.table.begin(), m.table.end(), [&](const auto& p) { return p[1] != m.table.front()[1]; });
    return m.formula != DispersionFormula::Constant;
}

double abbeNumber(const Medium& m) {
    if (!isDispersive(m)) return 0;
    const double nd = refractiveIndex(m, kWavelengthD);
    return (nd - 1) / (refractiveIndex(m, kWavelengthF) - refractiveIndex(m, kWavelengthC));
}

}  // namespace lenslab
