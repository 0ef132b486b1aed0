#include "trace/NearAxis.h"

#include <algorithm>
#include <cmath>

#include "prescription/OpticsError.h"

namespace lenslab {

double nearAxisHeight(const LensSystem& lens) {
    double smallest = lens.surfaces.front().apertureRadius;
    for (const Surface& s : lens.surfaces) smallest = std::min(smallest, s.apertureRadius);
    return 1e-4 * std::max(smallest, 1e-3);
}

double zAtHeight(const Ray& r, double y) {
    if (r.direction.y == 0) throw AfocalError("the ray leaves parallel to the axis (afocal system)");
    return r.origin.z + (y - r.origin.y) * r.direction.z / r.direction.y;
}

double heightAtZ(const Ray& r, double z) {
    return r.origin.y + (z - r.origin.z) * r.direction.y / r.direction.z;
}

Ray traceNearAxis(const LensSystem& lens, const Ray& ray, TraceDirection direction, int begin,
                  int end) {
    TraceOptions options;
    options.begin = begin;
    options.end = end;
    options.ignoreApertures = true;
    const TraceResult r = traceRay(lens, ray, direction, options);
    if (!r.ok())
        throw OpticsError(std::string("a near-axis ray cannot pass surface ") +
                          std::to_string(r.surface + 1) + " (" + blockReasonName(r.blocked) + ")");
    return r.ray;
}

}  // namespace lenslab
