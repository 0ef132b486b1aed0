#include "analysis/Distortion.h"

#include <cmath>

#include "firstorder/ChiefRay.h"
#include "trace/ExactTrace.h"
#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"
#include "prescription/Pi.h"

namespace lenslab {

namespace {

}  // namespace

std::vector<DistortionSample> distortionCurve(const LensSystem& lens, const FirstOrder& fo, double maxFieldDegrees,
                                              int count) {
    if (count < 2 || !(maxFieldDegrees > 0 && maxFieldDegrees < 90))
        throw OpticsError("distortion: need at least 2 samples and a maximum field between 0 and 90 degrees");
    std::vector<DistortionSample> samples;
    for (int k = 0; k < count; ++k) {
        DistortionSample s;
        s.fieldDegrees = maxFieldDegrees * k / (count - 1);
        if (k == 0) {
            s.found = true;
            samples.push_back(s);
            continue;
        }
        s.paraxialHeight = fo.efl * std::tan(s.fieldDegrees * kPi / 180);
        if (const std::optional<Ray> in = chiefRay(lens, s.fieldDegrees)) {
            TraceOptions options;
            options.ignoreApertures = true;
            const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
            if (out.ok() && out.ray.direction.z < 0) {
                s.found = true;
                s.imageHeight = -heightAtZ(out.ray, fo.zFPrime);
                s.distortionPercent = 100 * (s.imageHeight - s.paraxialHeight) / s.paraxialHeight;
            }
        }
        samples.push_back(s);
    }
    return samples;
}

}  // namespace lenslab
