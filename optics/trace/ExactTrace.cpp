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
    // A shaped aperture replaces the circle (stepThroughGeneral tests it); an automatic one clips nothing.
    const bool clips = !s.clearShape && (s.isStop || (!s.automaticAperture && !options.stopApertureOnly));
    if (!options.ignoreApertures && clips) c.apertureRadius2 = T(s.apertureRadius * s.apertureRadius);
    if (!options.ignoreApertures && !options.ignoreObscurations && !s.obscurationShape)
        c.obscurationRadius2 = T(s.obscurationRadius * s.obscurationRadius);
    c.eta = T(direction == TraceDirection::SceneToFilm ? nScene / nFilm : nFilm / nScene);
    c.beyondAperture = static_cast<int>(s.isStop ? BlockReason::ClippedByStop : BlockReason::OutsideAperture);
    c.reflects = s.mirror ? T(1) : T(0);
    if (s.isAspheric()) {
        c.asphericTerms = kAsphericTerms;
        while (s.aspheric[c.asphericTerms - 1] == 0) --c.asphericTerms;
        for (int k = 0; k < c.asphericTerms; ++k) c.aspheric[k] = T(s.aspheric[k]);
    }
    return c;
}

template SurfaceConstants<float> surfaceConstants<float>(const LensSystem&, int, TraceDirection, const TraceOptions&);
template SurfaceConstants<double> surfaceConstants<double>(const LensSystem&, int, TraceDirection, const TraceOptions&);

template <class T>
GeneralSurface<T> generalSurface(const LensSystem& lens, const Surface& s, const TraceOptions& options) {
    GeneralSurface<T> g;
    g.virtualPropagation = lens.decentred;
    g.form = FormConstants<T>::of(s.form);
    if (!options.ignoreApertures && (s.isStop || !options.stopApertureOnly)) g.clear = s.clearShape;
    if (!options.ignoreApertures && !options.ignoreObscurations) g.obscuration = s.obscurationShape;
    return g;
}

template GeneralSurface<float> generalSurface<float>(const LensSystem&, const Surface&, const TraceOptions&);
template GeneralSurface<double> generalSurface<double>(const LensSystem&, const Surface&, const TraceOptions&);

bool takesGeneralStep(const LensSystem& lens, const Surface& s) { return lens.decentred || s.needsGeneralStep(); }

bool isDummy(const LensSystem& lens, int i) {
    const Surface& s = lens.surfaces[i];
    return lens.decentred && s.curvature == 0 && !s.mirror && !s.isStop && s.automaticAperture && !s.clearShape &&
           !s.obscurationShape && s.obscurationRadius == 0 && s.form.isEvenAsphere() && !s.isAspheric() &&
           s.indexAfter == lens.indexBefore(i);
}

namespace {

// Moves a ray's coordinates by a rigid motion (in the tracer's arithmetic).
template <class T>
void move(const RigidMotion& m, T& px, T& py, T& pz, T& dx, T& dy, T& dz) {
    const auto& r = m.rotation;
    const T x = px, y = py, z = pz, u = dx, v = dy, w = dz;
    px = T(r[0]) * x + T(r[1]) * y + T(r[2]) * z + T(m.shift[0]);
    py = T(r[3]) * x + T(r[4]) * y + T(r[5]) * z + T(m.shift[1]);
    pz = T(r[6]) * x + T(r[7]) * y + T(r[8]) * z + T(m.shift[2]);
    dx = T(r[0]) * u + T(r[1]) * v + T(r[2]) * w;
    dy = T(r[3]) * u + T(r[4]) * v + T(r[5]) * w;
    dz = T(r[6]) * u + T(r[7]) * v + T(r[8]) * w;
}

}  // namespace

RigidMotion motionInto(const Surface& s, TraceDirection direction) {
    return direction == TraceDirection::SceneToFilm ? s.before : s.after.inverse();
}

RigidMotion motionOutOf(const Surface& s, TraceDirection direction) {
    return direction == TraceDirection::SceneToFilm ? s.after : s.before.inverse();
}

Ray movedRay(const RigidMotion& m, const Ray& r) {
    Ray out = r;
    move(m, out.origin.x, out.origin.y, out.origin.z, out.direction.x, out.direction.y, out.direction.z);
    return out;
}

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
    // The path is recorded in the coordinates the ray started in (a folded lens's real layout).
    RigidMotion toStart;
    auto position = [&] {
        const auto p = toStart.applyToPoint({double(px), double(py), double(pz)});
        return Vec3{p[0], p[1], p[2]};
    };
    // Only a lens whose coordinates may move (decentres and tilts, shapes aligned on the axis ray, a
    // mirrored image space) pays for the motions, once per surface: the symmetric lens's loop is as before.
    const bool moves = !lens.isRotationallySymmetric() || lens.hasMirrors();
    auto moveBy = [&](const RigidMotion& m) {
        if (m.isIdentity()) return;
        move(m, px, py, pz, dx, dy, dz);
        if (options.path) toStart = m.inverse().then(toStart);
    };
    if (options.path) options.path->push_back(position());
    for (int k = 0; k < end - begin; ++k) {
        const int i = toFilm ? begin + k : end - 1 - k;
        const Surface& surface = lens.surfaces[i];
        if (moves) moveBy(motionInto(surface, direction));
        if (isDummy(lens, i)) {
            if (options.path) options.path->push_back(position());
            moveBy(motionOutOf(surface, direction));
            continue;
        }
        const SurfaceConstants<T> s = surfaceConstants<T>(lens, i, direction, options);
        const BlockReason why =
            takesGeneralStep(lens, surface)
                ? stepThroughGeneral<T>(px, py, pz, dx, dy, dz, s, generalSurface<T>(lens, surface, options), s.eta)
                : stepThroughSurface<T>(px, py, pz, dx, dy, dz, s, s.eta);
        if (why != BlockReason::None) {
            result.blocked = why;
            result.surface = i;
            break;
        }
        if (options.path) options.path->push_back(position());
        if (moves) moveBy(motionOutOf(surface, direction));
    }
    result.ray = {{double(px), double(py), double(pz)}, {double(dx), double(dy), double(dz)}};
    return result;
}

template TraceResult traceRayT<float>(const LensSystem&, const Ray&, TraceDirection, const TraceOptions&);
template TraceResult traceRayT<double>(const LensSystem&, const Ray&, TraceDirection, const TraceOptions&);

TraceResult traceRay(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                     const TraceOptions& options) {
    return traceRayT<double>(lens, ray, direction, options);
}

}  // namespace lenslab
