#include "LensFlags.h"

namespace lenslab {

void declareLensFlags(ArgParser& p) {
    p.option("--fstop", "N", "f-number, from the lens's widest to f/64 (default: the widest)");
    p.option("--focus", "MM", "focus distance from the front vertex in mm, or inf (default inf)");
    p.option("--wavelength", "NM", "wavelength in nm, 360-830 (default: the prescription's primary, else the d line 587.56)");
}

LensSettings lensFlags(const ArgParser& p) {
    LensSettings s;
    if (const auto fstop = p.number("--fstop")) s.fstop = Setting{*fstop, "--fstop"};
    if (p.has("--focus")) s.focusDistance = Setting{parseDistance(p.get("--focus"), "--focus"), "--focus"};
    if (const auto nm = p.number("--wavelength")) s.wavelength = Setting{*nm, "--wavelength"};
    return s;
}

}  // namespace lenslab
