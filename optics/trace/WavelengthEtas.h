#pragma once
// Every surface's index ratio tabulated over the visible wavelengths, so that a batch of rays of
// different wavelengths is traced in one pass (each ray refracting with its own wavelength's ratio)
// instead of one pass per wavelength, which would split a camera batch into slivers too small to
// vectorise. A ray's wavelength is taken to its band's centre; with 1 nm bands the index differs
// from the exact one by at most half a nanometre's dispersion (under 1e-4 for the densest flints).
#include <cstdint>
#include <vector>

#include "trace/ExactTrace.h"

namespace lenslab {

struct WavelengthEtas {
    double firstNm = 360;   // centre of band 0
    double bandNm = 1;      // band width
    int bands = 0;
    std::vector<double> eta;  // surface-major: eta[surface * bands + band], as surfaceConstants gives it

    // The band holding wavelength nm (clamped to the table).
    std::uint16_t band(double nm) const;
    double bandCentreNm(int band) const { return firstNm + bandNm * band; }
    const double* etasOf(int surface) const { return eta.data() + std::size_t(surface) * bands; }
};

// The ratios of `lens` at band centres firstNm, firstNm + bandNm, ... up to lastNm, for a trace in
// `direction`: band k's ratios are those of atWavelength(lens, centre k), to the bit.
WavelengthEtas tabulateEtas(const LensSystem& lens, TraceDirection direction, double firstNm = 360,
                            double lastNm = 830, double bandNm = 1);

}  // namespace lenslab
