#pragma once
// Exact sequential ray tracing through the lens surfaces, in either direction.
#include <vector>

#include "prescription/LensSystem.h"
#include "trace/SurfaceStep.h"
#include "trace/Vec3.h"

namespace lenslab {

enum class TraceDirection { SceneToFilm, FilmToScene };

struct TraceOptions {
    // Surfaces [begin, end) take part (indices front to rear); end < 0 means up to the last one.
    int begin = 0;
    int end = -1;
    bool ignoreApertures = false;     // for first-order (paraxial-limit) rays
    bool ignoreObscurations = false;  // for the rim rays that set the f-number
    std::vector<Vec3>* path = nullptr;  // when set, receives the start and every surface hit
};

struct TraceResult {
    Ray ray;                            // the ray leaving the last surface, or where it was blocked
    BlockReason blocked = BlockReason::None;
    int surface = -1;                   // the surface that blocked it
    bool ok() const { return blocked == BlockReason::None; }
};

// Surface i's constants for a trace in `direction` (the index ratio depends on it).
template <class T>
SurfaceConstants<T> surfaceConstants(const LensSystem& lens, int i, TraceDirection direction, const TraceOptions& options = {});

// Traces `ray` (lens space, unit direction) through the surfaces. SceneToFilm rays travel toward -z
// and meet the surfaces front to rear; FilmToScene rays travel toward +z, rear to front.
TraceResult traceRay(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                     const TraceOptions& options = {});

// The same trace carried out in Scalar arithmetic (float or double; both instantiated), to measure
// what a float renderer would lose. Input, output and the lens stay double.
template <class Scalar>
TraceResult traceRayT(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                      const TraceOptions& options = {});

}  // namespace lenslab
