#include "firstorder/Pupils.h"

#include <cmath>

#include "trace/AxisRay.h"
#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

// The stop's own frame, as seen by rays leaving it: its centre (0, 0, z), the direction they leave
// in along the axis, and the direction across it in the meridional plane. Square to the axis that
// is the z axis, turned by mirrors; a decentred or tilted stop is met by the axis ray obliquely.
struct StopAxes {
    Vec3 along, across;
};
StopAxes stopAxes(const LensSystem& lens, TraceDirection direction) {
    // Light leaving the stop toward the film, or (traced back) toward the scene; mirrors turn it.
    const double dz = direction == TraceDirection::FilmToScene ? -lens.zDirectionAfter(lens.stopIndex - 1)
                                                               : lens.zDirectionAfter(lens.stopIndex);
    if (!lens.decentred) return {{0, 0, dz}, {0, 1, 0}};
    const std::optional<AxisAtStop> axis = axisRayAtStop(lens);
    if (!axis) throw OpticsError("no axis ray passes the stop's centre");
    const Vec3 a = direction == TraceDirection::FilmToScene ? -axis->arriving : axis->leaving;
    return {a, normalize(Vec3{0, 1, 0} - a.y * a)};
}

// Images the stop through surfaces [begin, end) in the given direction.
Pupil imageOfStop(const LensSystem& lens, TraceDirection direction, int begin, int end, const char* which) {
    const Surface& stop = lens.stop();
    const double h = nearAxisHeight(lens);
    Pupil p;
    try {
        const StopAxes axes = stopAxes(lens, direction);
        // Rays start in the stop's frame; the trace takes them from the coordinates after it.
        const RigidMotion leaving = motionOutOf(stop, direction);
        const auto trace = [&](const Ray& inStop) {
            return traceNearAxis(lens, movedRay(leaving, inStop), direction, begin, end);
        };
        const Vec3 centre{0, 0, stop.z};
        // A ray from the stop centre crosses the axis (extended) at the image of the stop centre.
        p.z = paraxialLimit([&](double u) { return axisCrossingZ(trace({centre, normalize(axes.along + u * axes.across)})); },
                            1e-4);  // slope of the ray: small enough for the O(u^4) remainder to vanish
        // A ray from an off-axis stop point, along the axis, passes (extended) through its image.
        p.magnification = paraxialLimit(
            [&](double y) { return heightAtZ(trace({{0, y, stop.z}, axes.along}), p.z) / y; }, h);
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
