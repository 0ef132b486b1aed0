#pragma once
// The chief ray of a distant object's field: the ray from the scene at that angle that passes
// through the centre of the aperture stop. It defines the field's image height (distortion, lateral
// colour) and where off-axis pupils are aimed.
#include <optional>

#include "prescription/LensSystem.h"
#include "trace/Vec3.h"

namespace lenslab {

// The incoming chief ray for a field angle: aimed so that, refracted by the elements in front of
// the stop, it crosses the stop plane on the axis. Apertures are ignored (the chief ray is a property
// of the surfaces' shapes); nullopt when no ray through the stop centre exists at that angle.
std::optional<Ray> chiefRay(const LensSystem& lens, double fieldDegrees);

}  // namespace lenslab
