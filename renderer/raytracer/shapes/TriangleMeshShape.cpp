#include "shapes/TriangleMeshShape.h"

#include <algorithm>
#include <cmath>

#include "Render.h"

namespace lenslab {

namespace {

class TriangleMeshShape : public Shape {
public:
    TriangleMeshShape(MeshData mesh, bool flipNormals) : m_(std::move(mesh)), flip_(flipNormals) {}

    unsigned attach(RTCDevice device, RTCScene scene) const override {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<Vec3f*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3f), m_.p.size()));
        auto* ix = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(std::uint32_t), m_.indices.size() / 3));
        if (!v || !ix) {
            rtcReleaseGeometry(g);
            throw SceneError("Embree: out of memory for a mesh of " + std::to_string(m_.indices.size() / 3) + " triangles");
        }
        std::copy(m_.p.begin(), m_.p.end(), v);
        std::copy(m_.indices.begin(), m_.indices.end(), ix);
        rtcSetGeometryUserData(g, const_cast<TriangleMeshShape*>(this));
        if (m_.alpha) rtcSetGeometryIntersectFilterFunction(g, &TriangleMeshShape::cutIntersections);
        if (m_.shadowAlpha) rtcSetGeometryOccludedFilterFunction(g, &TriangleMeshShape::cutShadows);
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        return id;
    }

    void surface(Vec3f, Vec3f, float, unsigned prim, float b1, float b2, SurfaceHit& h) const override {
        const std::uint32_t* i = &m_.indices[3 * prim];
        const float b0 = 1.0f - b1 - b2;
        h.p = b0 * m_.p[i[0]] + b1 * m_.p[i[1]] + b2 * m_.p[i[2]];
        h.ng = orientedNormal(prim);
        h.ns = h.ng;
        h.dndu = h.dndv = {};
        if (!m_.n.empty()) {
            const Vec3f ns = b0 * m_.n[i[0]] + b1 * m_.n[i[1]] + b2 * m_.n[i[2]];
            const float len = length(ns);
            const float side = dot(ns, h.ng) >= 0 ? 1.0f : -1.0f;  // SurfaceHit: ns on ng's side
            if (len > 0) h.ns = (side / len) * ns;
            normalPartials(prim, h.dndu, h.dndv);
            h.dndu = side * h.dndu;
            h.dndv = side * h.dndv;
        }
        if (!m_.uv.empty()) {
            h.u = b0 * m_.uv[2 * i[0]] + b1 * m_.uv[2 * i[1]] + b2 * m_.uv[2 * i[2]];
            h.v = b0 * m_.uv[2 * i[0] + 1] + b1 * m_.uv[2 * i[1] + 1] + b2 * m_.uv[2 * i[2] + 1];
        } else {  // pbrt's default per-triangle (0,0), (1,0), (1,1)
            h.u = b1 + b2;
            h.v = b2;
        }
        partials(prim, h.dpdu, h.dpdv);
        if (!m_.n.empty()) shadingTangents(h.ns, h.dpdu, h.dpdv);
    }

    std::size_t primitiveCount() const override { return m_.indices.size() / 3; }

    float primitiveArea(std::size_t prim) const override {
        const std::uint32_t* i = &m_.indices[3 * prim];
        return 0.5f * length(cross(m_.p[i[1]] - m_.p[i[0]], m_.p[i[2]] - m_.p[i[0]]));
    }

    ShapeSample samplePrimitive(std::size_t prim, float u1, float u2) const override {
        const std::uint32_t* i = &m_.indices[3 * prim];
        const Vec3f p0 = m_.p[i[0]], e1 = m_.p[i[1]] - p0, e2 = m_.p[i[2]] - p0;
        const float r = std::sqrt(u1);
        return {p0 + (1 - r) * e1 + (u2 * r) * e2, orientedNormal(prim), 1.0f / primitiveArea(prim)};
    }

    float primitivePdf(std::size_t prim, const SurfaceHit&) const override { return 1.0f / primitiveArea(prim); }

private:
    // Embree's filter callbacks: a candidate hit where the cutout texture is 0 is rejected, and the
    // ray goes on to the next surface.
    static void cutIntersections(const RTCFilterFunctionNArguments* args) { cut(args, false); }
    static void cutShadows(const RTCFilterFunctionNArguments* args) { cut(args, true); }
    static void cut(const RTCFilterFunctionNArguments* args, bool shadow) {
        const auto* self = static_cast<const TriangleMeshShape*>(args->geometryUserPtr);
        const Texture& alpha = shadow ? *self->m_.shadowAlpha : *self->m_.alpha;
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] == 0) continue;
            const Vec3f o{RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                          RTCRayN_org_z(args->ray, args->N, i)};
            const Vec3f d{RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                          RTCRayN_dir_z(args->ray, args->N, i)};
            SurfaceHit h;
            self->surface(o, d, RTCRayN_tfar(args->ray, args->N, i), RTCHitN_primID(args->hit, args->N, i),
                          RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i), h);
            if (alpha.evaluate(h).x == 0) args->valid[i] = 0;
        }
    }

    // pbrt-v3's dp/du and dp/dv from the corners' (u, v), or any frame around the face normal when
    // those (u, v) span no area.
    void partials(std::size_t prim, Vec3f& dpdu, Vec3f& dpdv) const {
        const std::uint32_t* i = &m_.indices[3 * prim];
        const CornerUv c = cornerUv(prim);
        const Vec3f dp02 = m_.p[i[0]] - m_.p[i[2]], dp12 = m_.p[i[1]] - m_.p[i[2]];
        if (!c.degenerate()) {
            c.solve(dp02, dp12, dpdu, dpdv);
            if (length(cross(dpdu, dpdv)) > 0) return;
        }
        const Vec3f n = cross(m_.p[i[2]] - m_.p[i[0]], m_.p[i[1]] - m_.p[i[0]]);
        if (length(n) > 0) perpendiculars(normalize(n), dpdu, dpdv);
    }

    // pbrt-v3's dn/du and dn/dv of the interpolated vertex normals, the same way from the corners'
    // (u, v); when those span no area, pbrt-v3's frame around (n2 - n0) x (n1 - n0), taken as it
    // comes (not unit), or zero when the normals do not vary.
    void normalPartials(std::size_t prim, Vec3f& dndu, Vec3f& dndv) const {
        const std::uint32_t* i = &m_.indices[3 * prim];
        const CornerUv c = cornerUv(prim);
        if (!c.degenerate()) {
            c.solve(m_.n[i[0]] - m_.n[i[2]], m_.n[i[1]] - m_.n[i[2]], dndu, dndv);
            return;
        }
        const Vec3f dn = cross(m_.n[i[2]] - m_.n[i[0]], m_.n[i[1]] - m_.n[i[0]]);
        if (dot(dn, dn) > 0) perpendiculars(dn, dndu, dndv);
        else dndu = dndv = {};
    }

    // The (u, v) differences of corners 0 and 1 from corner 2, which turn differences of a
    // quantity over the corners into its partials along u and v.
    struct CornerUv {
        float du02, dv02, du12, dv12;
        float det() const { return du02 * dv12 - dv02 * du12; }
        bool degenerate() const { return std::fabs(det()) < 1e-8f; }
        void solve(Vec3f d02, Vec3f d12, Vec3f& ddu, Vec3f& ddv) const {
            ddu = (dv12 * d02 - dv02 * d12) / det();
            ddv = (du02 * d12 - du12 * d02) / det();
        }
    };
    CornerUv cornerUv(std::size_t prim) const {
        const std::uint32_t* i = &m_.indices[3 * prim];
        float uv[3][2] = {{0, 0}, {1, 0}, {1, 1}};
        if (!m_.uv.empty())
            for (int k = 0; k < 3; ++k) {
                uv[k][0] = m_.uv[2 * i[k]];
                uv[k][1] = m_.uv[2 * i[k] + 1];
            }
        return {uv[0][0] - uv[2][0], uv[0][1] - uv[2][1], uv[1][0] - uv[2][0], uv[1][1] - uv[2][1]};
    }

    // pbrt-v3's shading tangents on a mesh with normals: unit, around the shading normal, from dp/du
    // (they come out opposite to dp/du and dp/dv, which pbrt-v3 keeps; see SurfaceHit).
    static void shadingTangents(Vec3f ns, Vec3f& dpdu, Vec3f& dpdv) {
        const float len = length(dpdu);
        const Vec3f s = len > 0 ? dpdu / len : dpdu;
        const Vec3f t = cross(s, ns);
        if (length(t) > 0) {
            dpdv = normalize(t);
            dpdu = cross(dpdv, ns);
        } else {
            perpendiculars(ns, dpdu, dpdv);
        }
    }

    // pbrt-v3's CoordinateSystem: two vectors completing n to a right-handed frame (unit when n is).
    static void perpendiculars(Vec3f n, Vec3f& a, Vec3f& b) {
        a = std::fabs(n.x) > std::fabs(n.y) ? Vec3f{-n.z, 0, n.x} / std::sqrt(n.x * n.x + n.z * n.z)
                                            : Vec3f{0, n.z, -n.y} / std::sqrt(n.y * n.y + n.z * n.z);
        b = cross(n, a);
    }

    // pbrt-v3's rule: the face normal (p1 - p0) x (p2 - p0) turned toward the shading normals when the
    // mesh has them, otherwise flipped by ReverseOrientation or a mirroring transform.
    Vec3f orientedNormal(std::size_t prim) const {
        const std::uint32_t* i = &m_.indices[3 * prim];
        Vec3f n = cross(m_.p[i[1]] - m_.p[i[0]], m_.p[i[2]] - m_.p[i[0]]);
        const float len = length(n);
        n = len > 0 ? n / len : Vec3f{0, 0, 1};
        if (!m_.n.empty()) {
            if (dot(n, m_.n[i[0]] + m_.n[i[1]] + m_.n[i[2]]) < 0) n = -n;
        } else if (flip_) {
            n = -n;
        }
        return n;
    }

    MeshData m_;
    bool flip_;
};

}  // namespace

std::shared_ptr<const Shape> makeTriangleMesh(MeshData mesh, const Transform& objectToGroup, bool reverseOrientation) {
    for (Vec3f& p : mesh.p) p = transformPoint(objectToGroup, p);
    for (Vec3f& n : mesh.n) {
        n = transformNormal(objectToGroup, n);
        const float len = length(n);
        if (len > 0) n = n / len;
    }
    return std::make_shared<TriangleMeshShape>(std::move(mesh), reverseOrientation != swapsHandedness(objectToGroup));
}

}  // namespace lenslab
