#pragma once
// The optical medium on one side of a surface: air, a plain index, a catalog glass or a model
// glass, evaluated at any wavelength. Indices are relative to air, as the glass makers publish
// them, so air is exactly 1.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {

// The dispersion formulas the catalogs use, with the wavelength L in micrometres. Coefficients
// not used by a glass are 0.
enum class DispersionFormula : std::uint8_t {
    Constant,          // n = coefficients[0]
    // n^2 = 1 + A + sum_i Bi L^2 / (L^2 - Ci), coefficients A, B1, C1, B2, C2, ... (Ci in um^2):
    // Schott, Ohara, CDGM and Hikari's crystals; also the model glass (one term, A = 0).
    Sellmeier,
    // The Schott polynomial and the makers' extended forms of it (Hoya, Sumita, Hikari, Ohara,
    // CDGM; Code V's Laurent): n^2 = a0 + a1 L^2 + a2 L^4 + a9 L^6 + a3 L^-2 + a4 L^-4 + ... + a8 L^-12.
    SchottPolynomial,
    // The rest of Zemax's catalog formulas (GlassCatalogFile.h gives their numbers):
    Herzberger,      // n = A + B M + C M^2 + D L^2 + E L^4 + F L^6, M = 1 / (L^2 - 0.028)
    Conrady,         // n = n0 + A / L + B / L^3.5
    SellmeierTwo,    // n^2 = 1 + A + B1 L^2 / (L^2 - l1^2) + B2 / (L^2 - l2^2)
    HandbookOne,     // n^2 = A + B / (L^2 - C) - D L^2
    HandbookTwo,     // n^2 = A + B L^2 / (L^2 - C) - D L^2
    // Measured indices at listed wavelengths (Code V private catalogs, tables of a maker's data
    // sheet), interpolated by a natural cubic spline in the wavelength; held at the ends.
    Tabulated,
};

struct Medium {
    std::string name;     // "N-BK7", "air", "model 1.5168/64.17", or "" for a plain index
    std::string catalog;  // "SCHOTT", "OHARA", ...; "" for air, plain index and model glasses
    DispersionFormula formula = DispersionFormula::Constant;
    std::array<double, 12> coefficients{};  // formula-specific (Constant: coefficients[0] = the index)
    double minNm = 0, maxNm = 0;            // the data's valid range (0, 0: any)
    double nd = 1, vd = 0;                  // the maker's published nd, Vd (vd 0: no dispersion)
    std::vector<std::array<double, 2>> table;  // Tabulated: (nm, index), nm ascending
};

Medium air();
// Dispersion-free: the same index at every wavelength (the lens tables that give only N).
// Throws std::invalid_argument unless n is finite and positive.
Medium constantIndex(double n);
// A glass known only by nd and Vd (a Zemax model glass, a lens table's Abbe column): a
// one-term Sellmeier with n(d) = nd and nF - nC = (nd - 1) / Vd exactly (ModelGlass.cpp).
// Throws std::invalid_argument unless nd > 1 and Vd > 0, both finite.
Medium modelGlass(double nd, double vd);

// A tabulated medium: (nm, index) pairs in any order, at least two, all finite and positive, no
// wavelength twice. Throws std::invalid_argument otherwise.
Medium tabulatedMedium(const std::string& name, std::vector<std::array<double, 2>> pairs);

// The index at a wavelength in nm. Outside the data's valid range the formula is extrapolated,
// as lens design programs do; where that leaves the formula's domain (past a Sellmeier pole, or
// n < 1) the value at the nearest end of the valid range is held instead, and for a medium
// without a range its nd: never NaN. Throws std::invalid_argument for a wavelength that is not
// finite and positive.
double refractiveIndex(const Medium& m, double wavelengthNm);
bool isDispersive(const Medium& m);
// (n_d - 1) / (n_F - n_C) computed from the formula at the d, F and C lines; 0 for a medium
// without dispersion (the convention of Medium::vd).
double abbeNumber(const Medium& m);

}  // namespace lenslab
