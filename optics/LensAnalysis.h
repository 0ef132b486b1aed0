#pragma once
// Everything lenslab reports about a lens at one aperture and focus setting.
#include <optional>

#include "Aperture.h"
#include "FirstOrder.h"
#include "Focus.h"
#include "LensSystem.h"
#include "Pupils.h"
#include "ThickLens.h"

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
};

// fstop: nullopt for the widest; focusDistance in mm from the front vertex (infinity allowed).
// Throws OpticsError for requests outside the lens's ranges.
LensAnalysis analyzeLens(const LensSystem& lens, std::optional<double> fstop, double focusDistance);

}  // namespace lenslab
