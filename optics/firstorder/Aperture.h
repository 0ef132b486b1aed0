#pragma once
// f-number and stop opening. The f-number is defined by the image-side cone for an object at
// infinity: fstop = 1 / (2 sin theta), theta the angle of the marginal ray converging to F'.
#include <string>
#include <vector>

#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"

namespace lenslab {

// The narrowest f-number any front end accepts: the same everywhere (f/64, the smallest stop of
// large-format lenses). A lens slower than that at its widest has just its widest setting.
constexpr double kNarrowestFstop = 64.0;

struct ApertureRange {
    double fstopMin = 0;                // the widest the lens allows (table stop or an element clips)
    // kNarrowestFstop; fstopMin for a lens slower than that at its widest; for an obscured lens,
    // where its stop closes into the obscuration's shadow (past it no light passes on axis)
    double fstopMax = kNarrowestFstop;
    // The narrowest f-number lenslab offers (the API's fstop_max, the full stops, the range in
    // messages): fstopMax, or for an obscured lens 2% inside it at three significant digits (f/12.8
    // for the reflex lens's 13.08): near the shadow's edge the open ring has next to no width, and
    // focus and the analyses find no ray through it.
    double fstopMaxOffered = kNarrowestFstop;
    double stopDiameterMax = 0;   // the stop opening at fstopMin, mm
    // The cones pass the stop alone: the other apertures block the axis (an off-axis section of a
    // design used at its off-axis fields), so the stop sets the f-number.
    bool stopOnly = false;
};

// Finds the widest cone from F' that passes every surface with the stop at its table diameter (or,
// when no cone passes, the stop alone).
ApertureRange computeApertureRange(const LensSystem& lens, const FirstOrder& fo);

// The stop diameter (mm) for a requested f-number: the marginal ray leaving F' at theta =
// asin(1 / (2 fstop)) traced back to the stop plane. Throws OpticsError naming the range when the
// request lies outside it.
double stopDiameterForFstop(const LensSystem& lens, const FirstOrder& fo, const ApertureRange& range,
                            double fstop);

// The f-number whose marginal ray fills a stop opening of `diameter` mm: 1 / (2 sin theta) for the
// cone from F' that just fills the stop. Openings at or beyond the widest give fstopMin (as pbrt-v3
// clamps them). Throws OpticsError for a diameter that is not positive.
double fstopForStopDiameter(const LensSystem& lens, const FirstOrder& fo, const ApertureRange& range, double diameter);

// Full stops (powers of sqrt 2) from the first at or above fstopMin up to fstopMax, exact values.
// No default for fstopMax: an obscured lens's range ends before kNarrowestFstop.
std::vector<double> fullStops(double fstopMin, double fstopMax);
// The range offered as lenslab writes it ("f/2.02 to f/64"): each end at three significant digits,
// rounded inward, so that an f-number read off it is one the lens takes (f/6.71 for 6.70196).
std::string fstopRangeText(const ApertureRange& range);
// Steps of `step` from fstopMin (rounded up to the step) to fstopMax. Throws OpticsError for a step
// that is not positive or a list longer than 100000.
std::vector<double> fineStops(double fstopMin, double fstopMax, double step = 0.1);

}  // namespace lenslab
