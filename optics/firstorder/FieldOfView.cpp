#include "firstorder/FieldOfView.h"

#include <cmath>
#include <vector>

#include "firstorder/ChiefRay.h"
#include "firstorder/FirstOrder.h"
#include "prescription/NumberText.h"
#include "trace/ExactTrace.h"
#include "trace/NearAxis.h"

namespace lenslab {

std::optional<double> chiefRayHeight(const LensSystem& lens, double fieldDegrees, double z, bool clipped) {
    const std::optional<Ray> in = chiefRay(lens, fieldDegrees);
    if (!in) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = !clipped;
    options.ignoreObscurations = true;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    if (!out.ok() || !(out.ray.direction.z * lens.zDirectionAfter(int(lens.surfaces.size()) - 1) > 0)) return std::nullopt;
    return heightAtZ(out.ray, z);
}

FieldOfView lensFieldOfView(const LensSystem& lens) {
    const double z = computeFirstOrder(lens).zFPrime;
    auto passes = [&](double field) { return chiefRayHeight(lens, field, z, true).has_value(); };
    if (passes(kWidestSearchedField))
        return {std::nullopt, "none: the lens passes chief rays at every angle up to " + formatNumber(kWidestSearchedField) +
                                  " deg (no aperture limits its field); give the fields in degrees"};
    // Bisection between a passing and a failing field.
    double lo = 0, hi = kWidestSearchedField;
    for (int it = 0; it < 32; ++it) {
        const double mid = 0.5 * (lo + hi);
        (passes(mid) ? lo : hi) = mid;
    }
    if (!(lo > 0)) return {std::nullopt, "none: no chief ray off the axis passes the clear apertures"};
    // The image height must grow with the field all the way out.
    constexpr int kSamples = 24;
    double previous = 0;
    for (int k = 1; k <= kSamples; ++k) {
        const double field = lo * k / kSamples;
        const std::optional<double> h = chiefRayHeight(lens, field, z, false);
        const double height = h ? std::fabs(*h) : 0.0;
        if (!(height > previous)) {
            const double last = lo * (k - 1) / kSamples;
            if (!(last > 0)) return {std::nullopt, "none: the lens forms no image off the axis"};
            return {last, "where the chief ray's image height stops growing with the field"};
        }
        previous = height;
    }
    return {lo, "the widest chief ray the clear apertures pass"};
}

}  // namespace lenslab
