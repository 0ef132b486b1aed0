#include "trace/ExactTrace.h"


namespace lenslab {

const char* blockReasonName(BlockReason reason) {
    switch (reason) {
        case BlockReason::None: return "none";
        case BlockReason::MissedSurface: return "missed surface";
        case BlockReason::OutsideAperture: return "outside clear aperture";
        case BlockReason::ClippedByStop: return "clipped by aperture stop";
        case BlockReason::TotalInternalReflection: return "total internal reflection";
        case BlockReason::Obscured: return "central obscuration";
    }
    return "unknown";
}

template <class T>
SurfaceConstants<T> surfaceConstants(const LensSystem& lens, int i, TraceDirection direction, const TraceOptions& options) {
    const Surface& s = lens.surfaces[i];
    const double nScene = lens.indexBefore(i), nFilm = s.indexAfter;
    SurfaceConstants<T> c;
    c.zVertex = T(s.z);
    c.curvature = T(s.curvature);
    c.radius = T(1) / T(s.curvature);
    c.conicFactor = T(1 + s.conic);
    if (!options.ignoreApertures) {
        c.apertureRadius2 = T(s.apertureRadius * s.apertureRadius);
        if (!options.ignoreObscurations) c.obscurationRadius2 = T(s.obscurationRadius * s.obscurationRadius);
    }
    c.eta = T(direction == TraceDirection::SceneToFilm ? nScene / nFilm : nFilm / nScene);
    c.isStop = s.isStop;
    c.mirror = s.mirror;
    if (s.isAspheric()) {
        c.asphericTerms = kAsphericTerms;
        while (s.aspheric[c.asphericTerms - 1] == 0) --c.asphericTerms;
        for (int k = 0; k < c.asphericTerms; ++k) c.aspheric[k] = T(s.aspheric[k]);
    }
    return c;
}

template SurfaceConstants<float> surfaceConstants<float>(const LensSystem&, int, TraceDirection, const TraceOptions&);
template SurfaceConstants<double> surfaceConstants<double>(const LensSystem&, int, TraceDirection, const TraceOptions&);

template <class Scalar>
TraceResult traceRayT(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                      const TraceOptions& options) {
    using T = Scalar;
    const int n = static_cast<int>(lens.surfaces.size());
    const int begin = options.begin;
    const int end = options.end < 0 ? n : options.end;
    const bool toFilm = direction == TraceDirection::SceneToFilm;

    TraceResult result;
    T px = T(ray.origin.x), py = T(ray.origin.y), pz = T(ray.origin.z);
    T dx = T(ray.direction.x), dy = T(ray.direction.y), dz = T(ray.direction.z);
    auto position = [&] { return Vec3{px, py, pz}; };
    if (options.path) options.path->push_back(position());
    for (int k = 0; k < end - begin; ++k) {
        const int i = toFilm ? begin + k : end - 1 - k;
        const BlockReason why =
            stepThroughSurface<T>(px, py, pz, dx, dy, dz, surfaceConstants<T>(lens, i, direction, options));
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
