#include "firstorder/FieldOfView.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "firstorder/ChiefRay.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Pupils.h"
#include "prescription/OpticsError.h"
#include "prescription/NumberText.h"
#include "trace/ExactTrace.h"
#include "trace/NearAxis.h"

namespace lenslab {

std::optional<double> chiefRayHeight(const LensSystem& lens, double fieldDegrees, double z, bool clipped) {
    const std::optional<Ray> in = chiefRay(lens, fieldDegrees);
    if (!in) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = !clipped;
    options.ignoreObscurations = true;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    if (!out.ok() || !(out.ray.direction.z * lens.zDirectionAfter(int(lens.surfaces.size()) - 1) > 0)) return std::nullopt;
    return heightAtZ(out.ray, z);
}

namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

// The field whose real chief ray lands at height h on the plane z: the height grows with the field
// from the axis, so the first sampled field past h and the one before bracket it for a bisection.
std::optional<double> fieldAtRealImageHeight(const LensSystem& lens, double h, double z) {
    double lo = 0;
    for (double field = 1; field < kWidestSearchedField; field += 1) {
        const std::optional<double> at = chiefRayHeight(lens, field, z, false);
        if (!at || !(std::fabs(*at) > 0)) return std::nullopt;
        if (std::fabs(*at) >= h) {
            double hi = field;
            for (int it = 0; it < 48; ++it) {
                const double mid = 0.5 * (lo + hi);
                const std::optional<double> m = chiefRayHeight(lens, mid, z, false);
                if (!m) return std::nullopt;
                (std::fabs(*m) < h ? lo : hi) = mid;
            }
            return 0.5 * (lo + hi);
        }
        lo = field;
    }
    return std::nullopt;
}

// The largest field of the prescription's own list as an object angle: angles as listed; an image
// height as the field whose chief ray lands there on the focal plane (paraxial: h = f tan(field);
// real: the traced chief ray) for a distant object; an object height as its angle from the entrance
// pupil. nullopt when the list has nothing off the axis, or a form this lens cannot turn into an
// angle (an image height for a near object, an object height for a distant one).
std::optional<FieldOfView> listedFieldOfView(const LensSystem& lens, const FirstOrder& fo) {
    double largest = 0;
    for (const FieldPoint& p : lens.fields.points) largest = std::max(largest, std::hypot(p.x, p.y));
    if (!(largest > 0)) return std::nullopt;
    const std::string listed = "the prescription's field list: " + formatNumber(largest) + " " +
                               (lens.fields.type == FieldType::ObjectAngle ? "deg" : "mm") + " " +
                               fieldTypeName(lens.fields.type);
    const bool distant = std::isinf(lens.objectDistance);
    std::optional<double> degrees;
    switch (lens.fields.type) {
        case FieldType::ObjectAngle: degrees = largest; break;
        case FieldType::ParaxialImageHeight:
            if (distant) degrees = std::atan(largest / std::fabs(fo.efl)) * kDegrees;
            break;
        case FieldType::RealImageHeight:
            if (distant) degrees = fieldAtRealImageHeight(lens, largest, fo.zFPrime);
            break;
        case FieldType::ObjectHeight:
            if (!distant) {
                try {
                    const double objectZ = lens.frontZ() + lens.objectDistance;
                    degrees = std::atan(largest / (objectZ - computePupils(lens).entrance.z)) * kDegrees;
                } catch (const OpticsError&) {
                    degrees = std::nullopt;  // a telecentric object space: no angle
                }
            }
            break;
    }
    if (!degrees || !(*degrees > 0 && *degrees < kWidestSearchedField)) return std::nullopt;
    return FieldOfView{degrees, lens.fields.type == FieldType::ObjectAngle ? listed : listed + " (" + formatNumber(*degrees, 4) + " deg)"};
}

}  // namespace

FieldOfView lensFieldOfView(const LensSystem& lens) {
    const FirstOrder fo = computeFirstOrder(lens);
    if (std::optional<FieldOfView> listed = listedFieldOfView(lens, fo)) return *listed;
    const double z = fo.zFPrime;
    auto passes = [&](double field) { return chiefRayHeight(lens, field, z, true).has_value(); };
    if (passes(kWidestSearchedField))
        return {std::nullopt, "none: the lens passes chief rays at every angle up to " + formatNumber(kWidestSearchedField) +
                                  " deg (no aperture limits its field); give the fields in degrees"};
    // Bisection between a passing and a failing field.
    double lo = 0, hi = kWidestSearchedField;
    for (int it = 0; it < 32; ++it) {
        const double mid = 0.5 * (lo + hi);
        (passes(mid) ? lo : hi) = mid;
    }
    if (!(lo > 0)) return {std::nullopt, "none: no chief ray off the axis passes the clear apertures"};
    // The image height must grow with the field all the way out.
    constexpr int kSamples = 24;
    double previous = 0;
    for (int k = 1; k <= kSamples; ++k) {
        const double field = lo * k / kSamples;
        const std::optional<double> h = chiefRayHeight(lens, field, z, false);
        const double height = h ? std::fabs(*h) : 0.0;
        if (!(height > previous)) {
            const double last = lo * (k - 1) / kSamples;
            if (!(last > 0)) return {std::nullopt, "none: the lens forms no image off the axis"};
            return {last, "where the chief ray's image height stops growing with the field"};
        }
        previous = height;
    }
    return {lo, "the widest chief ray the clear apertures pass"};
}

}  // namespace lenslab
