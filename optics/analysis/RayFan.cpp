#include "analysis/RayFan.h"

#include <limits>
#include <stdexcept>

#include "trace/ExactTrace.h"

namespace lenslab {

namespace {

std::optional<Vec3> imagePoint(const LensSystem& lens, const FieldAim& aim, double imageZ, double px, double py) {
    const std::optional<Ray> in = aimedRay(lens, aim, px, py);
    if (!in) return std::nullopt;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm);
    if (!out.ok()) return std::nullopt;
    return pointOnPlane(out.ray, imageZ);
}

}  // namespace

RayFan rayFan(const LensSystem& lens, const FieldAim& aim, double imageZ, Point2 reference, int samples) {
    if (samples < 2) throw std::invalid_argument("ray fan: need at least 2 samples");
    constexpr double kBlocked = std::numeric_limits<double>::quiet_NaN();
    RayFan fan;
    fan.wavelength = lens.wavelength;
    for (int k = 0; k < samples; ++k) {
        const double p = -1 + 2.0 * k / (samples - 1);
        fan.pupil.push_back(p);
        const auto t = imagePoint(lens, aim, imageZ, 0, p);
        const auto s = imagePoint(lens, aim, imageZ, p, 0);
        fan.tangential.push_back(t ? t->y - reference.y : kBlocked);
        fan.sagittal.push_back(s ? s->x - reference.x : kBlocked);
    }
    return fan;
}

}  // namespace lenslab
