#include "trace/RayTransfer.h"

namespace lenslab {

RayTransfer operator*(const RayTransfer& m, const RayTransfer& n) {
    return {m.a * n.a + m.b * n.c, m.a * n.b + m.b * n.d, m.c * n.a + m.d * n.c, m.c * n.b + m.d * n.d};
}

RayTransfer rayTransfer(const LensSystem& lens, double zFrom, int end, double zTo) {
    RayTransfer m;
    double z = zFrom, travel = -1, n = 1;  // travel: the sign of dz along the light
    const auto transfer = [&](double zNext) {
        m = RayTransfer{1, travel * (zNext - z), 0, 1} * m;
        z = zNext;
    };
    for (int k = 0; k < end; ++k) {
        const Surface& s = lens.surfaces[k];
        transfer(s.z);
        // The curvature as the travelling light sees it: positive when the centre lies ahead.
        const double c = -travel * s.vertexCurvature();
        if (s.mirror) {
            m = RayTransfer{1, 0, 2 * c, 1} * m;  // slope in the reversed frame
            travel = -travel;
        } else {
            const double next = s.indexAfter;
            m = RayTransfer{1, 0, -(next - n) * c / next, n / next} * m;
            n = next;
        }
    }
    transfer(zTo);
    return m;
}

}  // namespace lenslab
