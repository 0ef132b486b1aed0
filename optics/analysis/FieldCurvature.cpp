#include "analysis/FieldCurvature.h"

#include <cmath>

#include "trace/ExactTrace.h"
#include "analysis/PupilAiming.h"

namespace lenslab {

namespace {

// Half-width of the thin fans, in normalised pupil coordinates: far from the rim (the limit is
// local), far above rounding. Symmetric pairs cancel the fans' even terms (coma) to first order.
constexpr double kThinFan = 1e-3;

std::optional<Ray> exitRay(const LensSystem& lens, const FieldAim& aim, double px, double py) {
    const std::optional<Ray> in = aimedRay(lens, aim, px, py);
    if (!in) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = true;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    if (!out.ok()) return std::nullopt;
    return out.ray;
}

// The z where two rays have the same coordinate (x when `alongX`, else y).
double meetingZ(const Ray& a, const Ray& b, bool alongX) {
    auto coordinate = [alongX](const Ray& r) { return alongX ? r.origin.x : r.origin.y; };
    auto slope = [alongX](const Ray& r) { return (alongX ? r.direction.x : r.direction.y) / r.direction.z; };
    return (coordinate(b) - coordinate(a) + a.origin.z * slope(a) - b.origin.z * slope(b)) / (slope(a) - slope(b));
}

}  // namespace

std::vector<FieldCurvatureSample> fieldCurvature(const LensSystem& lens, double objectZ, double imageZ,
                                                 const std::vector<double>& fieldDegrees) {
    std::vector<FieldCurvatureSample> samples;
    for (double field : fieldDegrees) {
        FieldCurvatureSample s;
        s.fieldDegrees = field;
        if (const std::optional<FieldAim> aim = aimField(lens, {field, objectZ})) {
            const auto tPlus = exitRay(lens, *aim, 0, kThinFan), tMinus = exitRay(lens, *aim, 0, -kThinFan);
            const auto sPlus = exitRay(lens, *aim, kThinFan, 0), sMinus = exitRay(lens, *aim, -kThinFan, 0);
            if (tPlus && tMinus && sPlus && sMinus) {
                s.found = true;
                s.tangentialZ = meetingZ(*tPlus, *tMinus, false);
                s.sagittalZ = meetingZ(*sPlus, *sMinus, true);
                s.tangentialShift = s.tangentialZ - imageZ;
                s.sagittalShift = s.sagittalZ - imageZ;
            }
        }
        samples.push_back(s);
    }
    return samples;
}

}  // namespace lenslab
