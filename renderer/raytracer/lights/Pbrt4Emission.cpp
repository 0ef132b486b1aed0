#include "lights/Pbrt4Emission.h"

namespace lenslab {

Vec3f pbrt4Emission(const ParamSet& p, const std::string& name) {
    const float scale = float(p.getFloat("scale", 1));
    Vec3f e = p.getRgb(name, {1, 1, 1});
    if (p.isSpectral(name)) {
        const float y = luminance(e);
        if (!(y > 0)) p.fail("\"" + name + "\" has no luminance to normalise");
        e = e / y;
    }
    return scale * e;
}

float pbrt4PowerFactor(const ParamSet& p, float unitPower) {
    const double power = p.getFloat("power", -1);
    return power > 0 ? float(power) / unitPower : 1.0f;
}

}  // namespace lenslab
