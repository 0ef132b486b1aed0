#pragma once
// PROVISIONAL (replaced by the glass branch): an optical medium evaluated at any wavelength.
#include <array>
#include <cstdint>
#include <string>

namespace lenslab {

enum class DispersionFormula : std::uint8_t { Constant };

struct Medium {
    std::string name;
    std::string catalog;
    DispersionFormula formula = DispersionFormula::Constant;
    std::array<double, 12> coefficients{};
    double minNm = 0, maxNm = 0;
    double nd = 1, vd = 0;
};

Medium air();
Medium constantIndex(double n);
Medium modelGlass(double nd, double vd);
double refractiveIndex(const Medium& m, double wavelengthNm);
bool isDispersive(const Medium& m);

}  // namespace lenslab
namespace lenslab {
double abbeNumber(const Medium& m);
}
