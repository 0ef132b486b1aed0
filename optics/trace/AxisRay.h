#pragma once
// The optical axis ray of a decentred or tilted lens: the ray of the zero field through the centre of
// the stop. First order, pupils and focus are measured along it: alongAxisRay re-expresses the lens
// so that this ray enters and leaves along the z axis, and the rest of lenslab works unchanged.
#include <optional>

#include "trace/ExactTrace.h"

namespace lenslab {

// Where a ray from the scene meets the stop, in the stop's own frame (its centre at (0, 0, z);
// apertures ignored); nullopt when it cannot get there.
std::optional<Vec3> stopCrossing(const LensSystem& lens, const Ray& ray);

// The zero field's ray through the stop's centre (in the stop's own frame), in object-space
// coordinates: parallel to the z axis for an object at infinity, from the axial object point
// otherwise. nullopt when no such ray passes (apertures ignored).
std::optional<Ray> axisRay(const LensSystem& lens);

// The axis ray at the stop, in the stop's own frame: its directions arriving and (refracted or
// reflected by the stop's surface) leaving toward the film; for a decentred or tilted stop these
// are not the stop's normal. nullopt when no axis ray passes.
struct AxisAtStop {
    Vec3 arriving, leaving;
};
std::optional<AxisAtStop> axisRayAtStop(const LensSystem& lens);

// The lens with its object space shifted across z so that the axis ray enters on the z axis, and its
// image space turned about the last vertex and shifted so that the ray leaves along -z on the axis.
// The last vertex keeps its z. A lens whose axis ray is the z axis already comes back unchanged, and
// so does one through which no axis ray passes.
LensSystem alongAxisRay(const LensSystem& lens);

}  // namespace lenslab
