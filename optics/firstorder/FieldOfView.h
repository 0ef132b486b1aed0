#pragma once
// How far off axis a lens is analysed: its largest field (docs/analysis.md, "Fields"). A field is the
// angle of a distant object's chief ray to the axis in object space. The largest field comes, in
// this order, from the prescription's own field list, from what the caller images (a render's film
// diagonal), or from the lens itself: the widest field whose chief ray passes every clear aperture,
// but never past where the lens stops forming an image of it. A lens that limits neither (a doublet
// with its stop at the glass passes chief rays at any angle) has no largest field, and says so.
#include <optional>
#include <string>

#include "prescription/LensSystem.h"

namespace lenslab {

struct FieldOfView {
    std::optional<double> largestDegrees;  // none: the lens does not define one
    std::string source;                    // where it comes from, or why there is none
};

// The widest field this module searches: chief rays steeper than this pass any lens that does not
// clip them, so reaching it means the lens sets no limit.
constexpr double kWidestSearchedField = 89.0;

// The largest field of the prescription's own field list (angles as listed; image heights of a
// distant object and object heights of a near one turned into angles), else that of the lens
// alone, at the lens's wavelength. The chief ray is tested against the
// clear apertures but not against central obscurations: an obscured system (a reflex lens) blocks
// its chief ray by design, and its field is still the one its rims allow. Where the chief ray's real
// image height on the paraxial image plane of a distant object stops growing with the field, the
// lens no longer forms an image of the wider fields, and the field ends there.
FieldOfView lensFieldOfView(const LensSystem& lens);

// The chief ray of a field on the plane z: its height (y, lens space); nullopt when no chief ray
// exists or, with `clipped`, when it misses a clear aperture (central obscurations never clip it).
std::optional<double> chiefRayHeight(const LensSystem& lens, double fieldDegrees, double z, bool clipped);

}  // namespace lenslab
