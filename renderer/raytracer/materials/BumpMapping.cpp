// pbrt-v3's bump mapping: the surface displaced along its shading normal by a float texture d, whose
// partials dp'/du = dp/du + (dd/du) n + d dn/du and dp'/dv = dp/dv + (dd/dv) n + d dn/dv give the new
// shading normal (the last terms: the normal turns under the displaced point, by d over the radius
// of curvature). dd/du and dd/dv are forward differences of the texture at the point and (u, v)
// shifted by pbrt-v3's step for rays without differentials (lenslab's rays have none).
#include "materials/Material.h"

namespace lenslab {

namespace {

constexpr float kStep = 0.0005f;

float displacement(const Texture& d, const SurfaceHit& h) { return d.evaluate(h).x; }

}  // namespace

void Material::applyBump(SurfaceHit& h) const {
    if (!bump_) return;
    SurfaceHit shifted = h;
    shifted.p = h.p + kStep * h.dpdu;
    shifted.u = h.u + kStep;
    const float alongU = displacement(*bump_, shifted);
    shifted.p = h.p + kStep * h.dpdv;
    shifted.u = h.u;
    shifted.v = h.v + kStep;
    const float alongV = displacement(*bump_, shifted);
    const float here = displacement(*bump_, h);

    const Vec3f dpdu = h.dpdu + ((alongU - here) / kStep) * h.ns + here * h.dndu;
    const Vec3f dpdv = h.dpdv + ((alongV - here) / kStep) * h.ns + here * h.dndv;
    const Vec3f n = cross(dpdu, dpdv);
    const float len = length(n);
    if (!(len > 0) || !allFinite(n)) return;  // no partials at this hit: nothing to tilt
    // The displaced normal stays on the geometric normal's side, as pbrt-v3 turns it.
    h.ns = dot(n, h.ng) < 0 ? -(n / len) : n / len;
    h.dpdu = dpdu;
    h.dpdv = dpdv;
}

}  // namespace lenslab
