#include "firstorder/FirstOrder.h"

#include <cmath>

#include "prescription/AutomaticApertures.h"
#include "trace/ExactTrace.h"
#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

// A flat surface between equal media (a dummy, a baffle's plane) turns no ray; every other does.
bool bendsLight(const LensSystem& lens, int i) {
    const Surface& s = lens.surfaces[i];
    return s.mirror || s.curvature != 0 || s.isAspheric() || !s.form.isEvenAsphere() || s.indexAfter != lens.indexBefore(i);
}

// Where the axis, traced from a focal point at z = focusZ toward the lens, meets the outermost
// surface that bends light (a decentred lens's dummy surfaces and baffles beyond it do not):
// its z in the coordinates the ray starts in. A decentred or tilted lens's vertices lie off its
// axis ray, so its focal distances are measured from these points, not from the vertices; a
// centred lens's axis meets every surface at its vertex.
double axisMeetsOutermostSurfaceZ(const LensSystem& lens, double focusZ, TraceDirection towardLens, double vertexZ) {
    if (!lens.decentred) return vertexZ;
    std::vector<Vec3> path;
    TraceOptions o;
    o.ignoreApertures = true;
    o.path = &path;
    const double dz = towardLens == TraceDirection::FilmToScene ? 1.0 : -1.0;
    const TraceResult r = traceRay(lens, {{0, 0, focusZ}, {0, 0, dz}}, towardLens, o);
    const int n = static_cast<int>(lens.surfaces.size());
    // path[k + 1] is the k-th surface met: from the rear toward the film's side, from the front otherwise.
    for (int k = 0; k + 1 < static_cast<int>(path.size()); ++k) {
        const int i = towardLens == TraceDirection::FilmToScene ? n - 1 - k : k;
        if (bendsLight(lens, i)) return r.surface == i && !r.ok() ? vertexZ : path[k + 1].z;
    }
    return vertexZ;
}

}  // namespace

FirstOrder computeFirstOrder(const LensSystem& lens) {
    // No power along the axis (flat surfaces only, or terms from r^4 on): afocal at first order,
    // whatever rays at a finite height make of the higher terms.
    if (!std::isfinite(paraxialFocalLength(lens))) throw AfocalError("the lens is afocal: it has no power along its axis");
    const double h = nearAxisHeight(lens);
    // Start the rays beyond the surface caps (a sag never exceeds the aperture radius).
    const double zIn = lens.frontZ() + lens.surfaces.front().apertureRadius + 1.0;
    const double zOut = lens.rearZ() - lens.surfaces.back().apertureRadius - 1.0;
    auto fromScene = [&](double y) {
        return traceNearAxis(lens, {{0, y, zIn}, {0, 0, -1}}, TraceDirection::SceneToFilm);
    };
    auto fromFilm = [&](double y) {
        return traceNearAxis(lens, {{0, y, zOut}, {0, 0, 1}}, TraceDirection::FilmToScene);
    };
    // Principal plane: where the extended outgoing ray is back at the incoming height.
    FirstOrder fo;
    fo.zFPrime = paraxialLimit([&](double y) { return axisCrossingZ(fromScene(y)); }, h);
    fo.zPPrime = paraxialLimit([&](double y) { return zAtHeight(fromScene(y), y); }, h);
    fo.zF = paraxialLimit([&](double y) { return axisCrossingZ(fromFilm(y)); }, h);
    fo.zP = paraxialLimit([&](double y) { return zAtHeight(fromFilm(y), y); }, h);
    fo.efl = fo.zPPrime - fo.zFPrime;
    fo.eflFront = fo.zF - fo.zP;
    fo.backFocalDistance = axisMeetsOutermostSurfaceZ(lens, fo.zFPrime, TraceDirection::FilmToScene, lens.rearZ()) - fo.zFPrime;
    fo.frontFocalDistance = fo.zF - axisMeetsOutermostSurfaceZ(lens, fo.zF, TraceDirection::SceneToFilm, lens.frontZ());
    if (!std::isfinite(fo.efl) || std::fabs(fo.efl) > 1e12)
        throw AfocalError("the lens is afocal: parallel rays leave parallel");
    return fo;
}

}  // namespace lenslab
