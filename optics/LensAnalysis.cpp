#include "LensAnalysis.h"

namespace lenslab {

LensAnalysis analyzeLens(const LensSystem& table, std::optional<double> fstop, double focusDistance) {
    LensAnalysis a;
    a.firstOrder = computeFirstOrder(table);
    a.aperture = computeApertureRange(table, a.firstOrder);
    a.fstop = fstop.value_or(a.aperture.fstopMin);
    a.stopDiameter = stopDiameterForFstop(table, a.firstOrder, a.aperture, a.fstop);
    a.lens = withStopDiameter(table, a.stopDiameter);
    a.pupils = computePupils(a.lens);
    a.thick = makeThickLens(a.firstOrder, a.pupils);
    a.focus = focusAt(a.lens, a.firstOrder, a.pupils, focusDistance);
    return a;
}

}  // namespace lenslab
