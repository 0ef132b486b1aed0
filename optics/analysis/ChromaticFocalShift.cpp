#include "analysis/ChromaticFocalShift.h"

#include "firstorder/Chromatic.h"
#include "firstorder/FirstOrder.h"

namespace lenslab {

namespace {

double paraxialImageZAt(const LensSystem& lens, double objectZ, double wavelength) {
    const LensSystem at = atWavelength(lens, wavelength);
    return paraxialImageZ(at, computeFirstOrder(at), objectZ);
}

}  // namespace

std::vector<FocalShiftSample> chromaticFocalShift(const LensSystem& lens, double objectZ,
                                                  const std::vector<double>& wavelengths) {
    const double zD = paraxialImageZAt(lens, objectZ, kWavelengthD);
    std::vector<FocalShiftSample> samples;
    for (double nm : wavelengths) {
        const double z = paraxialImageZAt(lens, objectZ, nm);
        samples.push_back({nm, z, z - zD});
    }
    return samples;
}

}  // namespace lenslab
