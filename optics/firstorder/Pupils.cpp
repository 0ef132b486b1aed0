#include "firstorder/Pupils.h"

#include <cmath>

#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

// Images the stop through surfaces [begin, end) in the given direction.
Pupil imageOfStop(const LensSystem& lens, TraceDirection direction, int begin, int end, const char* which) {
    const Surface& stop = lens.stop();
    const double h = nearAxisHeight(lens);
    // Light leaving the stop toward the film, or (traced back) toward the scene; mirrors turn it.
    const double dz = direction == TraceDirection::FilmToScene ? -lens.zDirectionAfter(lens.stopIndex - 1)
                                                               : lens.zDirectionAfter(lens.stopIndex);
    Pupil p;
    try {
        // A ray from the stop centre crosses the axis (extended) at the image of the stop centre.
        p.z = paraxialLimit(
            [&](double u) {
                const Ray out = traceNearAxis(lens, {{0, 0, stop.z}, normalize({0, u, dz})}, direction, begin, end);
                return axisCrossingZ(out);
            },
            1e-4);  // slope of the ray: small enough for the O(u^4) remainder to vanish
        // A ray from an off-axis stop point, parallel to the axis, passes (extended) through its image.
        p.magnification = paraxialLimit(
            [&](double y) {
                const Ray out = traceNearAxis(lens, {{0, y, stop.z}, {0, 0, dz}}, direction, begin, end);
                return heightAtZ(out, p.z) / y;
            },
            h);
    } catch (const OpticsError& e) {
        throw OpticsError(std::string(which) + " pupil: " + e.what());
    }
    if (!std::isfinite(p.z) || std::fabs(p.z) > 1e12)
        throw OpticsError(std::string(which) + " pupil is at infinity (telecentric)");
    p.diameter = 2.0 * stop.apertureRadius * std::fabs(p.magnification);
    return p;
}

}  // namespace

Pupils computePupils(const LensSystem& lens) {
    const int s = lens.stopIndex;
    const int n = static_cast<int>(lens.surfaces.size());
    return {imageOfStop(lens, TraceDirection::FilmToScene, 0, s, "entrance"),
            imageOfStop(lens, TraceDirection::SceneToFilm, s + 1, n, "exit")};
}

}  // namespace lenslab
