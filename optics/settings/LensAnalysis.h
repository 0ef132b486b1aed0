#pragma once
// Everything lenslab reports about a lens at one aperture and focus setting.
#include <optional>
#include <string>

#include "firstorder/Aperture.h"
#include "firstorder/Chromatic.h"
#include "firstorder/FieldOfView.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Focus.h"
#include "settings/LensSettings.h"
#include "prescription/LensSystem.h"
#include "firstorder/Pupils.h"
#include "firstorder/ThickLens.h"

namespace lenslab {

struct LensAnalysis {
    LensSystem lens;          // with the stop opened to stopDiameter
    FirstOrder firstOrder;
    ApertureRange aperture;
    double fstop = 0;         // requested, or the widest
    double stopDiameter = 0;  // mm
    Pupils pupils;            // at this stop opening
    ThickLens thick;
    FocusResult focus;
    FieldOfView field;        // the lens's largest field, at its primary wavelength
    Chromatic chromatic;      // F, d and C at this focus; lateral colour at the largest field
    // describeLens only: the lens is afocal (nothing above `lens` is set), or its first order is
    // known but no aperture and focus could be found (the reason; firstOrder set, nothing after it).
    bool afocal = false;
    std::string incomplete;
};

// The one check of lens settings: the wavelength within 360-830 nm, the aperture within [the lens's widest, f/64] (or a stop diameter
// within the stop), the focus reachable, the film behind the rear vertex, at most one way of
// giving each. Throws OpticsError whose message starts with the offending setting's source.
LensAnalysis analyzeLens(const LensSystem& lens, const LensSettings& settings);

// analyzeLens, or as much of it as the lens allows, for the places that describe a lens rather than
// use it (the lens command): an afocal lens (a test system of flat mirrors and plates) with `afocal`
// set; a lens with first-order data but no aperture or focus at infinity (a finite-conjugate design
// whose F' lies inside it) with `incomplete` saying why. A setting's own error is still thrown.
LensAnalysis describeLens(const LensSystem& lens, const LensSettings& settings);

// Shorthand for code and tests with plain numbers: fstop nullopt for the widest; focusDistance in
// mm from the front vertex (infinity allowed).
LensAnalysis analyzeLens(const LensSystem& lens, std::optional<double> fstop, double focusDistance);

}  // namespace lenslab
