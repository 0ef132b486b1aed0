#include "analysis/Obscuration.h"

#include "trace/ExactTrace.h"

namespace lenslab {

double axialObscuration(const LensSystem& lens, const FieldAim& axis) {
    auto obscured = [&](double radius) {
        const std::optional<Ray> in = aimedRay(lens, axis, 0, radius);
        if (!in) return false;
        return traceRay(lens, *in, TraceDirection::SceneToFilm).blocked == BlockReason::Obscured;
    };
    if (!obscured(0)) return 0;
    // The first radius of a sweep that is not obscured, then bisection back to the edge.
    constexpr int kSweep = 64;
    double lo = 0, hi = 0;
    for (int k = 1; k <= kSweep && hi == 0; ++k)
        if (!obscured(double(k) / kSweep)) hi = double(k) / kSweep;
        else lo = double(k) / kSweep;
    if (hi == 0) return 1;  // the whole pupil is obscured
    for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        (obscured(mid) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace lenslab
