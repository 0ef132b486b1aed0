#include "trace/WavelengthEtas.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

std::uint16_t WavelengthEtas::band(double nm) const {
    const double k = std::round((nm - firstNm) / bandNm);
    return std::uint16_t(std::clamp(k, 0.0, double(bands - 1)));
}

WavelengthEtas tabulateEtas(const LensSystem& lens, TraceDirection direction, double firstNm, double lastNm,
                            double bandNm) {
    WavelengthEtas t;
    t.firstNm = firstNm;
    t.bandNm = bandNm;
    t.bands = int(std::floor((lastNm - firstNm) / bandNm + 1e-9)) + 1;
    const int n = int(lens.surfaces.size());
    t.eta.resize(std::size_t(n) * t.bands);
    for (int k = 0; k < t.bands; ++k) {
        const LensSystem atBand = atWavelength(lens, t.bandCentreNm(k));
        for (int i = 0; i < n; ++i) t.eta[std::size_t(i) * t.bands + k] = surfaceConstants<double>(atBand, i, direction).eta;
    }
    return t;
}

}  // namespace lenslab
