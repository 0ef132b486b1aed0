#pragma once
// Paraxial quantities measured with the exact tracer: a quantity traced with rays at height h has
// the form v(h) = v0 + a h^2 + O(h^4) by symmetry, so Richardson extrapolation of v(h) and v(h/2)
// gives the paraxial limit v0 to O(h^4) without writing a second (paraxial) tracer.
#include "trace/ExactTrace.h"

namespace lenslab {

template <class F>
double paraxialLimit(F&& valueAtHeight, double h) {
    return (4.0 * valueAtHeight(0.5 * h) - valueAtHeight(h)) / 3.0;
}

// Height used for near-axis rays: small against the lens, large against rounding.
double nearAxisHeight(const LensSystem& lens);

// For a meridional ray (x = 0): the z where it reaches height y (the axis for y = 0; throws
// OpticsError if it runs parallel to the axis), and its height at a given z.
double zAtHeight(const Ray& r, double y);
inline double axisCrossingZ(const Ray& r) { return zAtHeight(r, 0.0); }
double heightAtZ(const Ray& r, double z);

// Traces a near-axis ray ignoring apertures; throws OpticsError if it cannot pass (TIR, missed).
Ray traceNearAxis(const LensSystem& lens, const Ray& ray, TraceDirection direction, int begin = 0,
                  int end = -1);

}  // namespace lenslab
