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

template <class Scalar>
TraceResult traceRayT(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                      const TraceOptions& options) {
    using T = Scalar;
    const int n = static_cast<int>(lens.surfaces.size());
    const int begin = options.begin;
    const int end = options.end < 0 ? n : options.end;
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    const T inf = std::numeric_limits<T>::infinity();

    TraceResult result;
    T px = T(ray.origin.x), py = T(ray.origin.y), pz = T(ray.origin.z);
    T dx = T(ray.direction.x), dy = T(ray.direction.y), dz = T(ray.direction.z);
    auto position = [&] { return Vec3{px, py, pz}; };
    if (options.path) options.path->push_back(position());
    for (int k = 0; k < end - begin; ++k) {
        const int i = toFilm ? begin + k : end - 1 - k;
        const Surface& s = lens.surfaces[i];
        const double nScene = lens.indexBefore(i), nFilm = s.indexAfter;
        const T eta = T(toFilm ? nScene / nFilm : nFilm / nScene);
        const T r2 = options.ignoreApertures ? inf : T(s.apertureRadius * s.apertureRadius);
        const BlockReason why =
            stepThroughSurface<T>(px, py, pz, dx, dy, dz, T(s.z), T(s.curvature), T(1) / T(s.curvature), r2, eta, s.isStop);
        if (why != BlockReason::None) {
            result.blocked = why;
            result.surface = i;
            break;
        }
        if (options.path) options.path->push_back(position());
    }
    result.ray = {position(), {dx, dy, dz}};
    return result;
}

template TraceResult traceRayT<float>(const LensSystem&, const Ray&, TraceDirection, const TraceOptions&);
template TraceResult traceRayT<double>(const LensSystem&, const Ray&, TraceDirection, const TraceOptions&);

TraceResult traceRay(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                     const TraceOptions& options) {
    return traceRayT<double>(lens, ray, direction, options);
}

}  // namespace lenslab
