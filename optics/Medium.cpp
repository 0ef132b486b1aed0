#include "Medium.h"

#include <stdexcept>

namespace lenslab {

Medium air() { return constantIndex(1.0); }
Medium constantIndex(double n) {
    Medium m;
    m.coefficients[0] = n;
    m.nd = n;
    return m;
}
Medium modelGlass(double nd, double vd) {
    // provisional: Cauchy n = A + B / lambda^2 through nd and nF - nC
    Medium m = constantIndex(nd);
    m.vd = vd;
    m.name = "model";
    return m;
}
double refractiveIndex(const Medium& m, double) { return m.coefficients[0]; }
bool isDispersive(const Medium& m) { return m.vd > 0; }

}  // namespace lenslab
namespace lenslab {
double abbeNumber(const Medium& m) { return m.vd; }
}
