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
    bool stopApertureOnly = false;    // only the stop clips (an off-axis section's f-number)
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
// Whether a surface of the lens takes the general step (its form or shapes, or a decentred lens), and
// what that step needs of it.
bool takesGeneralStep(const LensSystem& lens, const Surface& s);
// A dummy surface of a decentred lens (flat, between equal media, clipping nothing): it only places
// the coordinates of the surfaces after it, so the trace moves the ray's coordinates and not the
// ray. A ray grazing its plane (a reference plane at a fold's focus) would meet it nowhere useful.
bool isDummy(const LensSystem& lens, int i);
template <class T>
GeneralSurface<T> generalSurface(const LensSystem& lens, const Surface& s, const TraceOptions& options = {});

// The motions of a ray's coordinates on its way through a decentred or tilted surface, for a trace
// in `direction`: into the surface's frame before it is met, and on to the next surface's after.
RigidMotion motionInto(const Surface& s, TraceDirection direction);
RigidMotion motionOutOf(const Surface& s, TraceDirection direction);
// The ray in the coordinates the motion m takes its own to (origin and direction both moved).
Ray movedRay(const RigidMotion& m, const Ray& r);

// Traces `ray` (lens space, unit direction) through the surfaces. SceneToFilm rays travel toward -z
// and meet the surfaces front to rear; FilmToScene rays travel toward +z, rear to front. Through a
// decentred or tilted lens the ray arrives in the coordinates of the surfaces around surface `begin`
// (SceneToFilm; `end` FilmToScene) and leaves in those around the other end of the range: for the
// whole lens, object space and image space (where the film lies across z). options.path is recorded
// in the coordinates the ray started in.
TraceResult traceRay(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                     const TraceOptions& options = {});

// The same trace carried out in Scalar arithmetic (float or double; both instantiated), to measure
// what a float renderer would lose. Input, output and the lens stay double.
template <class Scalar>
TraceResult traceRayT(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                      const TraceOptions& options = {});

}  // namespace lenslab
