#include "ExactTrace.h"

#include <limits>

namespace lenslab {

const char* blockReasonName(BlockReason reason) {
    switch (reason) {
        case BlockReason::None: return "none";
        case BlockReason::MissedSurface: return "missed surface";
        case BlockReason::OutsideAperture: return "outside clear aperture";
        case BlockReason::ClippedByStop: return "clipped by aperture stop";
        case BlockReason::TotalInternalReflection: return "total internal reflection";
    }
    return "unknown";
}

TraceResult traceRay(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                     const TraceOptions& options) {
    const int n = static_cast<int>(lens.surfaces.size());
    const int begin = options.begin;
    const int end = options.end < 0 ? n : options.end;
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    const double inf = std::numeric_limits<double>::infinity();

    TraceResult result;
    Vec3 p = ray.origin, d = ray.direction;
    if (options.path) options.path->push_back(p);
    for (int k = 0; k < end - begin; ++k) {
        const int i = toFilm ? begin + k : end - 1 - k;
        const Surface& s = lens.surfaces[i];
        const double nScene = lens.indexBefore(i), nFilm = s.indexAfter;
        const double eta = toFilm ? nScene / nFilm : nFilm / nScene;
        const double r2 = options.ignoreApertures ? inf : s.apertureRadius * s.apertureRadius;
        const BlockReason why =
            stepThroughSurface(p.x, p.y, p.z, d.x, d.y, d.z, s.z, s.curvature, r2, eta, s.isStop);
        if (why != BlockReason::None) {
            result.blocked = why;
            result.surface = i;
            break;
        }
        if (options.path) options.path->push_back(p);
    }
    result.ray = {p, d};
    return result;
}

}  // namespace lenslab
