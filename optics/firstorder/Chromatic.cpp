#include "firstorder/Chromatic.h"

#include <cmath>
#include <optional>

#include "firstorder/FieldOfView.h"
#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "trace/AxisRay.h"
#include "trace/NearAxis.h"

namespace lenslab {

double paraxialImageZ(const LensSystem& lens, const FirstOrder& fo, double objectZ) {
    // Near-axis rays from the object (or parallel to the axis, for an object at infinity) cross the
    // axis there in the limit of small heights.
    if (std::isinf(objectZ)) return fo.zFPrime;
    const double zVertex = lens.frontZ();
    return paraxialLimit(
        [&](double y) {
            const Ray in{{0, 0, objectZ}, normalize(Vec3{0, y, zVertex - objectZ})};
            return axisCrossingZ(traceNearAxis(lens, in, TraceDirection::SceneToFilm));
        },
        nearAxisHeight(lens));
}

Chromatic computeChromatic(const LensSystem& lens, double objectZ, std::optional<double> fieldDegrees) {
    Chromatic out;
    if (!lens.isDispersive()) {
        // One index at every wavelength: nothing to spread.
        const LensSystem d = atWavelength(lens, kWavelengthD);
        const FirstOrder fo = computeFirstOrder(d);
        out.eflF = out.eflD = out.eflC = fo.efl;
        out.imageZF = out.imageZD = out.imageZC = paraxialImageZ(d, fo, objectZ);
        if (fieldDegrees && *fieldDegrees > 0)
            if (const std::optional<double> h = chiefRayHeight(d, *fieldDegrees, out.imageZD, false))
                out.lateral = LateralColour{0, *fieldDegrees, *h};
        return out;
    }
    const LensSystem f = atWavelength(lens, kWavelengthF);
    const LensSystem d = atWavelength(lens, kWavelengthD);
    const LensSystem c = atWavelength(lens, kWavelengthC);
    // First order along each wavelength's own axis ray: in a decentred or tilted lens (a tilted
    // plate) the glass moves the axis ray differently at F, d and C, and near-axis rays measured
    // about another wavelength's axis give nothing like a focal length. The image planes keep the
    // last vertex's z, so the longitudinal colour compares like with like.
    const LensSystem fAxis = alongAxisRay(f), dAxis = alongAxisRay(d), cAxis = alongAxisRay(c);
    const FirstOrder foF = computeFirstOrder(fAxis), foD = computeFirstOrder(dAxis), foC = computeFirstOrder(cAxis);
    out.eflF = foF.efl;
    out.eflD = foD.efl;
    out.eflC = foC.efl;
    out.imageZF = paraxialImageZ(fAxis, foF, objectZ);
    out.imageZD = paraxialImageZ(dAxis, foD, objectZ);
    out.imageZC = paraxialImageZ(cAxis, foC, objectZ);
    out.longitudinalColour = out.imageZC - out.imageZF;
    if (fieldDegrees && *fieldDegrees > 0) {
        // Blue and red at the field the caller names, whatever their rims do, in the lens's own
        // frame: a tilted plate's sideways shift of blue against red is lateral colour too.
        const std::optional<double> hD = chiefRayHeight(d, *fieldDegrees, out.imageZD, false);
        const std::optional<double> hF = chiefRayHeight(f, *fieldDegrees, out.imageZD, false);
        const std::optional<double> hC = chiefRayHeight(c, *fieldDegrees, out.imageZD, false);
        if (hD && hF && hC) out.lateral = LateralColour{*hF - *hC, *fieldDegrees, *hD};
    }
    return out;
}

}  // namespace lenslab
