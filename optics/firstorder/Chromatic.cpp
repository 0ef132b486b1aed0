#include "firstorder/Chromatic.h"

#include <cmath>
#include <optional>

#include "firstorder/ChiefRay.h"
#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "trace/NearAxis.h"

namespace lenslab {

namespace {

// Height of the chief ray of a field on the plane z; with `clipped`, only when it passes every clear
// aperture.
std::optional<double> chiefHeight(const LensSystem& lens, double fieldDegrees, double z, bool clipped = true) {
    const std::optional<Ray> in = chiefRay(lens, fieldDegrees);
    if (!in) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = !clipped;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    if (!out.ok() || !(out.ray.direction.z < 0)) return std::nullopt;
    return heightAtZ(out.ray, z);
}

}  // namespace

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

double largestChiefRayField(const LensSystem& lens) {
    // Bisection between a passing and a failing field.
    constexpr double kWidest = 85.0;
    const double z = lens.rearZ();
    if (chiefHeight(lens, kWidest, z)) return kWidest;
    double lo = 0, hi = kWidest;
    for (int it = 0; it < 20; ++it) {
        const double mid = 0.5 * (lo + hi);
        (chiefHeight(lens, mid, z) ? lo : hi) = mid;
    }
    return lo;
}

Chromatic computeChromatic(const LensSystem& lens, double objectZ) {
    Chromatic out;
    if (!lens.isDispersive()) {
        // One index at every wavelength: nothing to spread (and no field to search).
        const LensSystem d = atWavelength(lens, kWavelengthD);
        const FirstOrder fo = computeFirstOrder(d);
        out.eflF = out.eflD = out.eflC = fo.efl;
        out.imageZF = out.imageZD = out.imageZC = paraxialImageZ(d, fo, objectZ);
        return out;
    }
    const LensSystem f = atWavelength(lens, kWavelengthF);
    const LensSystem d = atWavelength(lens, kWavelengthD);
    const LensSystem c = atWavelength(lens, kWavelengthC);
    const FirstOrder foF = computeFirstOrder(f), foD = computeFirstOrder(d), foC = computeFirstOrder(c);
    out.eflF = foF.efl;
    out.eflD = foD.efl;
    out.eflC = foC.efl;
    out.imageZF = paraxialImageZ(f, foF, objectZ);
    out.imageZD = paraxialImageZ(d, foD, objectZ);
    out.imageZC = paraxialImageZ(c, foC, objectZ);
    out.longitudinalColour = out.imageZC - out.imageZF;
    const double field = largestChiefRayField(d);
    out.lateralColourFieldDegrees = field;
    if (field > 0) {
        const std::optional<double> hD = chiefHeight(d, field, out.imageZD);
        // The field is set by the d light; blue and red at the same field are measured whatever
        // their rims do.
        const std::optional<double> hF = chiefHeight(f, field, out.imageZD, false);
        const std::optional<double> hC = chiefHeight(c, field, out.imageZD, false);
        out.lateralColourImageHeight = hD.value_or(0);
        if (hF && hC) out.lateralColour = *hF - *hC;
    }
    return out;
}

}  // namespace lenslab
