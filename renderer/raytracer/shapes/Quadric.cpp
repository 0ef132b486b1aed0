#include "shapes/Quadric.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Render.h"

namespace lenslab {

double azimuth(double x, double y) {
    const double phi = std::atan2(y, x);
    return phi < 0 ? phi + 2 * M_PI : phi;
}

namespace {

Vec3d apply(const Matrix44& m, Vec3d p, double w) {
    return {m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + w * m.m[0][3],
            m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + w * m.m[1][3],
            m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + w * m.m[2][3]};
}

Vec3f toFloat(Vec3d v) { return {float(v.x), float(v.y), float(v.z)}; }

Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

double determinant3(const Matrix44& a) {
    const auto& m = a.m;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Areas scale by one constant only under a similarity: the linear part's columns orthogonal and of
// equal length.
bool isSimilarity(const Matrix44& a) {
    const auto& m = a.m;
    double g[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) g[i][j] = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
    const double s2 = g[0][0], tol = 1e-9 * s2;
    return std::fabs(g[1][1] - s2) <= tol && std::fabs(g[2][2] - s2) <= tol && std::fabs(g[0][1]) <= tol &&
           std::fabs(g[0][2]) <= tol && std::fabs(g[1][2]) <= tol;
}

// Embree's user-geometry callbacks; lenslab traces single rays (rtcIntersect1/rtcOccluded1), so N is 1.
const Quadric& quadricOf(void* userPtr) { return *static_cast<const Quadric*>(userPtr); }

void quadricBounds(const RTCBoundsFunctionArguments* args) { *args->bounds_o = quadricOf(args->geometryUserPtr).groupBounds(); }

void quadricIntersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    RTCRay& r = rh->ray;
    float t;
    if (!quadricOf(args->geometryUserPtr).intersectGroupRay({r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z},
                                                            r.tnear, r.tfar, t))
        return;
    r.tfar = t;
    rh->hit.u = rh->hit.v = 0;
    rh->hit.Ng_x = rh->hit.Ng_y = 0;
    rh->hit.Ng_z = 1;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
}

void quadricOccluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    float t;
    if (quadricOf(args->geometryUserPtr).intersectGroupRay({r->org_x, r->org_y, r->org_z}, {r->dir_x, r->dir_y, r->dir_z},
                                                           r->tnear, r->tfar, t))
        r->tfar = -std::numeric_limits<float>::infinity();
}

}  // namespace

Quadric::Quadric(const Transform& objectToGroup, bool reverseOrientation, double phiMaxDegrees)
    : phiMax_(std::clamp(phiMaxDegrees, 0.0, 360.0) * M_PI / 180),
      objectToGroup_(objectToGroup),
      flip_(reverseOrientation != swapsHandedness(objectToGroup) ? -1.0f : 1.0f),
      similarityScale_(isSimilarity(objectToGroup.forward) ? std::cbrt(std::fabs(determinant3(objectToGroup.forward))) : 0) {}

Vec3f Quadric::toGroup(Vec3d p) const { return toFloat(apply(objectToGroup_.forward, p, 1)); }

Vec3d Quadric::toObject(Vec3f p) const { return apply(objectToGroup_.backward, {p.x, p.y, p.z}, 1); }
Vec3d Quadric::toObjectVector(Vec3f v) const { return apply(objectToGroup_.backward, {v.x, v.y, v.z}, 0); }

// The oriented unit normal in the group's space (by the inverse transpose, as pbrt-v3), and how much
// a small patch of surface at pObject grows from object to group space.
Vec3f Quadric::groupNormal(Vec3d pObject, double& areaScale) const {
    Vec3d n = normal(pObject);
    double len = std::sqrt(dot(n, n));
    n = len > 0 ? (1 / len) * n : Vec3d{0, 0, 1};  // the cone's apex has no normal
    const auto& w = objectToGroup_.backward.m;
    const Vec3d g{w[0][0] * n.x + w[1][0] * n.y + w[2][0] * n.z, w[0][1] * n.x + w[1][1] * n.y + w[2][1] * n.z,
                  w[0][2] * n.x + w[1][2] * n.y + w[2][2] * n.z};
    len = std::sqrt(dot(g, g));
    areaScale = std::fabs(determinant3(objectToGroup_.forward)) * len;
    return toFloat((flip_ / len) * g);
}

// The unit normal's partials in the group's space, oriented as groupNormal. In object space the
// Weingarten equations, as pbrt-v3: with the first fundamental form E, F, G and the second e, f, g,
// dn/du = ((f F - e G) dp/du + (e F - f E) dp/dv) / (E G - F^2), and dn/dv likewise. Zero where one
// partial all but vanishes (hits within rounding of the cone's apex or the paraboloid's vertex):
// e and f are rounding noise over a vanishing E there.
void Quadric::groupNormalPartials(Vec3d p, Vec3d dpdu, Vec3d dpdv, Vec3f& dndu, Vec3f& dndv) const {
    const double E = dot(dpdu, dpdu), F = dot(dpdu, dpdv), G = dot(dpdv, dpdv);
    const Vec3d n = cross(dpdu, dpdv);
    const double det = dot(n, n);  // E G - F^2
    if (!(det > 0) || std::min(E, G) < 1e-20 * std::max(E, G)) {
        dndu = dndv = {};
        return;
    }
    Vec3d duu, duv, dvv;
    secondPartials(p, duu, duv, dvv);
    const Vec3d unit = (1 / std::sqrt(det)) * n;
    const double e = dot(unit, duu), f = dot(unit, duv), g = dot(unit, dvv);
    const Vec3d nu = ((f * F - e * G) / det) * dpdu + ((e * F - f * E) / det) * dpdv;
    const Vec3d nv = ((g * F - f * G) / det) * dpdu + ((f * F - g * E) / det) * dpdv;
    dndu = flip_ * transformNormalPartial(objectToGroup_, toFloat(unit), toFloat(nu));
    dndv = flip_ * transformNormalPartial(objectToGroup_, toFloat(unit), toFloat(nv));
}

void Quadric::measure() {
    Vec3d lo, hi;
    bounds(lo, hi);
    float b[6] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                  -std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d c{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        const Vec3d g = apply(objectToGroup_.forward, c, 1);
        const double gv[3] = {g.x, g.y, g.z};
        for (int k = 0; k < 3; ++k) {
            const double pad = 1e-6 * (std::fabs(gv[k]) + 1e-3);  // float rounding must not cut the surface
            b[k] = std::min(b[k], float(gv[k] - pad));
            b[k + 3] = std::max(b[k + 3], float(gv[k] + pad));
        }
    }
    groupBounds_ = {b[0], b[1], b[2], 0, b[3], b[4], b[5], 0};

    if (similarityScale_ > 0) {
        groupArea_ = objectArea() * similarityScale_ * similarityScale_;
        return;
    }
    // Otherwise integrate the local area growth over the surface: the mean of growth / density over
    // a regular grid of samples.
    constexpr int kGrid = 64;
    double sum = 0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const Vec3d p = sample((i + 0.5) / kGrid, (j + 0.5) / kGrid);
            double growth;
            groupNormal(p, growth);
            sum += growth / objectPdf(p);
        }
    groupArea_ = sum / (kGrid * kGrid);
}

unsigned Quadric::attach(RTCDevice device, RTCScene scene) const {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcSetGeometryUserData(g, const_cast<Quadric*>(this));  // Embree's API is not const-aware
    rtcSetGeometryBoundsFunction(g, quadricBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, quadricIntersect);
    rtcSetGeometryOccludedFunction(g, quadricOccluded);
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    return id;
}

bool Quadric::intersectGroupRay(Vec3f o, Vec3f d, float tMin, float tMax, float& t) const {
    double th;
    if (!intersect(toObject(o), toObjectVector(d), tMin, tMax, th)) return false;
    t = float(th);
    return t > tMin && t < tMax;
}

bool Quadric::nearestRoot(double a, double b, double c, Vec3d o, Vec3d d, double tMin, double tMax, double& t) const {
    double roots[2];
    int n = 0;
    if (a == 0) {
        if (b == 0) return false;
        roots[n++] = -c / b;
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc < 0) return false;
        // The root formula without cancellation: q = -(b + sign(b) sqrt(disc)) / 2.
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        const double t0 = q / a, t1 = q != 0 ? c / q : t0;
        roots[n++] = std::min(t0, t1);
        roots[n++] = std::max(t0, t1);
    }
    for (int i = 0; i < n; ++i) {
        if (!(roots[i] > tMin && roots[i] < tMax)) continue;
        if (accepts(refine(o + roots[i] * d))) {
            t = roots[i];
            return true;
        }
    }
    return false;
}

void Quadric::surface(Vec3f o, Vec3f d, float t, unsigned, float, float, SurfaceHit& h) const {
    const Vec3d p = refine(toObject(o) + double(t) * toObjectVector(d));
    double u, v, growth;
    uv(p, u, v);
    h.u = float(u);
    h.v = float(v);
    h.p = toGroup(p);
    h.ng = h.ns = groupNormal(p, growth);
    Vec3d dpdu, dpdv;
    partials(p, dpdu, dpdv);
    h.dpdu = toFloat(apply(objectToGroup_.forward, dpdu, 0));
    h.dpdv = toFloat(apply(objectToGroup_.forward, dpdv, 0));
    groupNormalPartials(p, dpdu, dpdv, h.dndu, h.dndv);
}

ShapeSample Quadric::samplePrimitive(std::size_t, float u1, float u2) const {
    const Vec3d p = sample(u1, u2);
    double growth;
    ShapeSample s;
    s.n = groupNormal(p, growth);
    s.p = toGroup(p);
    s.pdf = float(objectPdf(p) / growth);
    return s;
}

float Quadric::primitivePdf(std::size_t, const SurfaceHit& at) const {
    const Vec3d p = refine(toObject(at.p));
    double growth;
    groupNormal(p, growth);
    return float(objectPdf(p) / growth);
}

}  // namespace lenslab
