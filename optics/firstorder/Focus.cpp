#include "firstorder/Focus.h"

#include <cmath>
#include <limits>
#include <string>

#include "trace/ExactTrace.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

std::string fmt(double v) { return formatNumber(v) + " mm"; }

// Meridional rays from the object through equal-area rings of the entrance pupil; the best focus
// minimises the RMS spot sum_i (a_i + m_i z)^2 of rays y = a_i + m_i z, a closed form.
void refineExact(const LensSystem& lens, const Pupils& pupils, FocusResult& r) {
    constexpr int kRings = 64;
    const double rp = 0.5 * pupils.entrance.diameter * 0.999;
    double sumAM = 0, sumMM = 0;
    int used = 0;
    for (int k = 0; k < kRings; ++k) {
        const double rho = rp * std::sqrt((k + 0.5) / kRings);
        Ray in;
        if (r.infinity) {
            in = {{0, rho, lens.frontZ() + lens.surfaces.front().apertureRadius + 1.0}, {0, 0, -1}};
        } else {
            const Vec3 target{0, rho, pupils.entrance.z};
            in = {{0, 0, r.objectZ}, normalize(target - Vec3{0, 0, r.objectZ})};
        }
        const TraceResult t = traceRay(lens, in, TraceDirection::SceneToFilm);
        if (!t.ok() || t.ray.direction.z >= 0) continue;
        const double m = t.ray.direction.y / t.ray.direction.z;
        const double a = t.ray.origin.y - t.ray.origin.z * m;
        sumAM += a * m;
        sumMM += m * m;
        ++used;
    }
    if (used == 0 || sumMM == 0)
        throw OpticsError("no exact ray from the object at " + fmt(r.objectZ) + " passes the lens");
    r.imageZExact = -sumAM / sumMM;
    r.raysUsed = used;
}

}  // namespace

double closestFocusDistance(const FirstOrder& fo) {
    // |m| = f / (zeta - f) with zeta the object distance from P.
    return fo.zP + fo.efl * (1.0 + 1.0 / kMaxMagnification);
}

FocusResult focusAt(const LensSystem& lens, const FirstOrder& fo, const Pupils& pupils, double distance) {
    FocusResult r;
    if (!(fo.efl > 0)) throw OpticsError("focusing needs a converging lens (EFL > 0)");
    if (std::isnan(distance) || distance <= 0)
        throw OpticsError("focus distance must be positive (mm in front of the front vertex)");
    r.infinity = std::isinf(distance);
    if (r.infinity) {
        r.objectZ = distance;
        r.imageZThick = fo.zFPrime;
    } else {
        r.objectZ = lens.frontZ() + distance;
        const double closest = closestFocusDistance(fo);
        if (r.objectZ <= fo.zF)
            throw OpticsError("focus distance " + fmt(distance) + " is inside the front focal length: the front focal point is " +
                              fmt(fo.zF - lens.frontZ()) + " in front of the lens and the closest focus " +
                              fmt(closest - lens.frontZ()));
        if (r.objectZ < closest)
            throw OpticsError("focus distance " + fmt(distance) + " is closer than this lens can focus: the closest is " +
                              fmt(closest - lens.frontZ()) + " (magnification " + std::to_string(int(kMaxMagnification)) + "x)");
        const double zeta = r.objectZ - fo.zP;
        r.imageZThick = fo.zPPrime - fo.efl * zeta / (zeta - fo.efl);
    }
    refineExact(lens, pupils, r);
    r.difference = r.imageZExact - r.imageZThick;
    return r;
}

double thickLensFocusForFilm(const LensSystem& lens, const FirstOrder& fo, double filmZ) {
    const double imageDistance = fo.zPPrime - filmZ;  // P' to the film, positive toward the film
    if (!(imageDistance > fo.efl)) return std::numeric_limits<double>::infinity();
    const double objectDistance = fo.efl * imageDistance / (imageDistance - fo.efl);  // from P
    return fo.zP + objectDistance - lens.frontZ();
}

FocusResult filmPlacedAt(const LensSystem& lens, const FirstOrder& fo, double filmZ) {
    if (!(filmZ < lens.rearZ()))
        throw OpticsError("the film must lie behind the rear vertex: film distance " + formatNumber(lens.rearZ() - filmZ) + " mm");
    FocusResult f;
    const double distance = thickLensFocusForFilm(lens, fo, filmZ);
    f.infinity = std::isinf(distance);
    f.objectZ = f.infinity ? distance : lens.frontZ() + distance;
    f.imageZThick = f.imageZExact = filmZ;
    return f;
}

}  // namespace lenslab
