#include "TradeoffCases.h"

#include <cmath>

namespace lenslab::tradeoff {

std::vector<LensCase> lensCases() {
    std::vector<LensCase> cases;
    for (const char* name : {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"})
        cases.push_back({name, std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name + ".dat"});
    return cases;
}

std::vector<StopCase> stopCases() { return {{std::nullopt, "widest"}, {5.6, "f/5.6"}, {11.0, "f/11"}}; }

std::vector<FieldCase> fieldCases() { return {{0.0, "centre"}, {0.5, "half"}, {1.0, "corner"}}; }

double filmDiagonalMm() { return std::hypot(kFilmWidthMm, kFilmHeightMm); }
double filmHalfDiagonalMm() { return 0.5 * filmDiagonalMm(); }

}  // namespace lenslab::tradeoff
