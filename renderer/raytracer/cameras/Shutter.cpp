#include "cameras/Shutter.h"

#include "prescription/NumberText.h"

namespace lenslab {

Shutter readShutter(const ParamSet& p) {
    const Shutter s{p.getFloat("shutteropen", 0), p.getFloat("shutterclose", 1)};
    if (s.close < s.open)
        p.fail("shutterclose (" + formatNumber(s.close) + ") comes before shutteropen (" + formatNumber(s.open) + ")");
    return s;
}

}  // namespace lenslab
