#include "prescription/AutomaticApertures.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

// A paraxial ray as (height, reduced slope omega = N u) in front of each surface, Code V's signs:
// s = -z along the unfolded axis, index N signed (negated at each mirror).
struct ParaxialRay {
    std::vector<double> height;  // at each surface
    double heightAtImage = 0;    // at the last surface's gap end
    double omegaOut = 0, indexOut = 1;
};

ParaxialRay traceParaxial(const LensSystem& lens, double y, double omega) {
    ParaxialRay ray;
    const int n = static_cast<int>(lens.surfaces.size());
    double index = 1;  // signed
    for (int k = 0; k < n; ++k) {
        const Surface& s = lens.surfaces[k];
        ray.height.push_back(y);
        const double after = s.mirror ? -index : (index < 0 ? -s.indexAfter : s.indexAfter);
        omega -= y * (after - index) * s.vertexCurvature();
        index = after;
        if (k + 1 < n) y += (s.z - lens.surfaces[k + 1].z) * omega / index;
    }
    ray.omegaOut = omega;
    ray.indexOut = index;
    ray.heightAtImage = y;
    return ray;
}

double largestField(const DesignFields& fields) {
    double largest = 0;
    for (const FieldPoint& p : fields.points) largest = std::max(largest, std::hypot(p.x, p.y));
    return largest;
}

}  // namespace

double paraxialFocalLength(const LensSystem& lens) {
    const ParaxialRay a = traceParaxial(lens, 1, 0);
    return a.omegaOut == 0 ? INFINITY : std::fabs(a.indexOut / a.omegaOut);
}

void setAutomaticApertures(LensSystem& lens, const LensTable& table) {
    const bool any = std::any_of(lens.surfaces.begin(), lens.surfaces.end(), [](const Surface& s) { return s.automaticAperture; });
    if (!any) return;
    const int stop = lens.stopIndex;
    const bool finite = std::isfinite(lens.objectDistance);
    const double distance = lens.objectDistance;
    // Two independent rays; every paraxial ray is a sum of them: A enters at height 1 parallel to the
    // axis, B at the first vertex with omega 1. From a finite object, the ray from its axis point at
    // omega w is w (L A + B).
    const ParaxialRay a = traceParaxial(lens, 1, 0), b = traceParaxial(lens, 0, 1);
    double ma = 0, mb = 0;  // marginal ray = ma A + mb B
    if (table.objectNumericalAperture && finite) {
        mb = *table.objectNumericalAperture;
        ma = distance * mb;
    } else if (table.entrancePupilDiameter || table.designFNumber) {
        const double epd = table.entrancePupilDiameter ? *table.entrancePupilDiameter
                                                       : paraxialFocalLength(lens) / *table.designFNumber;
        if (finite) {
            mb = 0.5 * epd / distance;
            ma = distance * mb;
        } else {
            ma = 0.5 * epd;
        }
    } else if (!lens.surfaces[stop].automaticAperture) {
        ma = lens.surfaces[stop].apertureRadius / a.height[stop];
    } else {
        throw LensTableError(lens.name, lens.surfaces[stop].line,
                             "the stop has no clear aperture and the file states no aperture (EPD, FNO or NAO)");
    }
    // Chief ray: through the stop's centre, scaled to the largest field.
    double ca = b.height[stop], cb = -a.height[stop];
    const double field = largestField(table.fields);
    double scale = 0;
    switch (table.fields.type) {
        case FieldType::ObjectAngle:
            scale = cb != 0 ? std::tan(field * kPi / 180) / cb : 0;
            break;
        case FieldType::ObjectHeight: {
            const double heightAtObject = finite ? ca - distance * cb : 0;
            scale = heightAtObject != 0 ? field / heightAtObject : 0;
            break;
        }
        case FieldType::ParaxialImageHeight:
        case FieldType::RealImageHeight: {
            const double h = ca * a.heightAtImage + cb * b.heightAtImage;
            scale = h != 0 ? field / h : 0;
            break;
        }
    }
    ca *= scale;
    cb *= scale;
    // A surface at a focus of the axial beam would get none: it keeps a thousandth of the widest.
    std::vector<double> radii(lens.surfaces.size(), 0.0);
    double widest = 0;
    for (std::size_t k = 0; k < lens.surfaces.size(); ++k) {
        const double marginal = std::fabs(ma * a.height[k] + mb * b.height[k]);
        const double chief = std::fabs(ca * a.height[k] + cb * b.height[k]);
        radii[k] = int(k) == stop ? marginal : 1.1 * (marginal + chief);
        widest = std::max(widest, radii[k]);
    }
    for (std::size_t k = 0; k < lens.surfaces.size(); ++k) {
        Surface& s = lens.surfaces[k];
        if (!s.automaticAperture) continue;
        const double radius = std::min(std::max(radii[k], 1e-3 * widest), 0.999 * sagDomainRadius(s));
        if (!(radius > 0) || !std::isfinite(radius))
            throw LensTableError(lens.name, s.line, "no clear aperture can be derived for this surface: give one (CIR)");
        s.apertureRadius = radius;
    }
}

}  // namespace lenslab
