#include "LensFlags.h"

namespace lenslab {

void declareLensFlags(ArgParser& p) {
    p.option("--fstop", "N", "f-number, from the lens's widest to f/64 (default: the widest)");
    p.option("--focus", "MM", "focus distance from the front vertex in mm, or inf (default inf)");
}

LensSettings lensFlags(const ArgParser& p) {
    LensSettings s;
    if (const auto fstop = p.number("--fstop")) s.fstop = Setting{*fstop, "--fstop"};
    if (p.has("--focus")) s.focusDistance = Setting{parseDistance(p.get("--focus"), "--focus"), "--focus"};
    return s;
}

}  // namespace lenslab
