#include "cameras/LensMount.h"

#include <cmath>

#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

constexpr double kMaxTurnDegrees = 45;
constexpr double kMaxShiftMm = 100;

void check(double value, double limit, const char* what, const char* unit) {
    if (!(std::fabs(value) <= limit))
        throw OpticsError(std::string("lens ") + what + " must lie within +-" + formatNumber(limit) + " " + unit + ", got " +
                          formatNumber(value));
}

}  // namespace

RigidMotion bodyFromLens(const LensMount& mount, double pivotZ) {
    check(mount.tiltDegrees, kMaxTurnDegrees, "tilt", "degrees");
    check(mount.swingDegrees, kMaxTurnDegrees, "swing", "degrees");
    check(mount.shiftMm[0], kMaxShiftMm, "shift x", "mm");
    check(mount.shiftMm[1], kMaxShiftMm, "shift y", "mm");
    const double t = mount.tiltDegrees * M_PI / 180, s = mount.swingDegrees * M_PI / 180;
    const double ct = std::cos(t), st = std::sin(t), cs = std::cos(s), ss = std::sin(s);
    // R = (about y by the swing) (about x by the tilt), right-handed: the axis (0, 0, 1) turns to
    // (cos t sin s, -sin t, cos t cos s).
    RigidMotion m;
    m.rotation = {cs, ss * st, ss * ct,  //
                  0, ct, -st,            //
                  -ss, cs * st, cs * ct};
    // p_body = R (p - pivot) + pivot + shift.
    m.shift = {mount.shiftMm[0] - m.rotation[2] * pivotZ, mount.shiftMm[1] - m.rotation[5] * pivotZ,
               pivotZ - m.rotation[8] * pivotZ};
    return m;
}

}  // namespace lenslab
