#include "firstorder/FirstOrder.h"

#include <cmath>

#include "prescription/AutomaticApertures.h"
#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"

namespace lenslab {

FirstOrder computeFirstOrder(const LensSystem& lens) {
    // No power along the axis (flat surfaces only, or terms from r^4 on): afocal at first order,
    // whatever rays at a finite height make of the higher terms.
    if (!std::isfinite(paraxialFocalLength(lens))) throw AfocalError("the lens is afocal: it has no power along its axis");
    const double h = nearAxisHeight(lens);
    // Start the rays beyond the surface caps (a sag never exceeds the aperture radius).
    const double zIn = lens.frontZ() + lens.surfaces.front().apertureRadius + 1.0;
    const double zOut = lens.rearZ() - lens.surfaces.back().apertureRadius - 1.0;
    auto fromScene = [&](double y) {
        return traceNearAxis(lens, {{0, y, zIn}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    };
    auto fromFilm = [&](double y) {
        return traceNearAxis(lens, {{0, y, zOut}, {0, 0, 1}}, TraceDirection::FilmToScene);
    };
    // Principal plane: where the extended outgoing ray is back at the incoming height.
    FirstOrder fo;
    fo.zFPrime = paraxialLimit([&](double y) { return axisCrossingZ(fromScene(y)); }, h);
    fo.zPPrime = paraxialLimit([&](double y) { return zAtHeight(fromScene(y), y); }, h);
    fo.zF = paraxialLimit([&](double y) { return axisCrossingZ(fromFilm(y)); }, h);
    fo.zP = paraxialLimit([&](double y) { return zAtHeight(fromFilm(y), y); }, h);
    fo.efl = fo.zPPrime - fo.zFPrime;
    fo.eflFront = fo.zF - fo.zP;
    fo.backFocalDistance = lens.rearZ() - fo.zFPrime;
    fo.frontFocalDistance = fo.zF - lens.frontZ();
    if (!std::isfinite(fo.efl) || std::fabs(fo.efl) > 1e12)
        throw AfocalError("the lens is afocal: parallel rays leave parallel");
    return fo;
}

}  // namespace lenslab
