#include "SceneGeometry.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "Render.h"

namespace lenslab {

namespace {

void reportEmbreeError(void*, RTCError code, const char* message) {
    // Errors surface through rtcGetDeviceError below; nothing to do here but keep Embree quiet.
    (void)code;
    (void)message;
}

void checkDevice(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw SceneError(std::string("Embree failed ") + what + " (error " + std::to_string(int(e)) + ")");
}

Vec3f faceNormal(const TriangleMesh& m, std::uint32_t prim) {
    const Vec3f& p0 = m.p[m.indices[3 * prim]];
    const Vec3f& p1 = m.p[m.indices[3 * prim + 1]];
    const Vec3f& p2 = m.p[m.indices[3 * prim + 2]];
    const Vec3f n = cross(p1 - p0, p2 - p0);
    const float len = length(n);
    return len > 0 ? n / len : Vec3f{0, 0, 1};
}

// pbrt's orientation rule: the face normal turned toward the shading normals when the mesh has
// them, otherwise flipped by ReverseOrientation or a mirroring transform.
Vec3f orientedFaceNormal(const TriangleMesh& m, std::uint32_t prim) {
    Vec3f n = faceNormal(m, prim);
    if (!m.n.empty()) {
        const Vec3f ns = m.n[m.indices[3 * prim]] + m.n[m.indices[3 * prim + 1]] + m.n[m.indices[3 * prim + 2]];
        if (dot(n, ns) < 0) n = -n;
    } else if (m.flipNormals) {
        n = -n;
    }
    return n;
}

}  // namespace

SceneGeometry::SceneGeometry(SceneDescription& scene) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw SceneError("Embree: cannot create a device");
    rtcSetDeviceErrorFunction(device_, reportEmbreeError, nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    lights_ = std::move(scene.lights);

    for (TriangleMesh& mesh : scene.meshes) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.p.size()));
        for (std::size_t i = 0; i < mesh.p.size(); ++i) {
            v[3 * i] = mesh.p[i].x;
            v[3 * i + 1] = mesh.p[i].y;
            v[3 * i + 2] = mesh.p[i].z;
        }
        auto* ix = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(unsigned), mesh.indices.size() / 3));
        for (std::size_t i = 0; i < mesh.indices.size(); ++i) ix[i] = mesh.indices[i];
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        checkDevice(device_, "adding a triangle mesh");
        if (id != meshes_.size()) throw SceneError("Embree: unexpected geometry id");
        MeshRecord rec;
        rec.mesh = std::move(mesh);
        if (rec.mesh.emission) {
            const std::size_t tris = rec.mesh.indices.size() / 3;
            for (std::size_t t = 0; t < tris; ++t) {
                const auto& m = rec.mesh;
                lights_.push_back(makeTriangleLight(m.p[m.indices[3 * t]], m.p[m.indices[3 * t + 1]],
                                                    m.p[m.indices[3 * t + 2]], orientedFaceNormal(m, std::uint32_t(t)),
                                                    m.emission->L, m.emission->twoSided));
                rec.triangleLights.push_back(lights_.back().get());
            }
        }
        meshes_.push_back(std::move(rec));
    }

    if (!scene.spheres.empty()) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), scene.spheres.size()));
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            const Sphere& s = scene.spheres[i];
            v[4 * i] = s.centre.x;
            v[4 * i + 1] = s.centre.y;
            v[4 * i + 2] = s.centre.z;
            v[4 * i + 3] = s.radius;
            SphereRecord rec{s, nullptr};
            if (s.emission) {
                lights_.push_back(makeSphereLight(s.centre, s.radius, s.flipNormals, s.emission->L, s.emission->twoSided));
                rec.light = lights_.back().get();
            }
            spheres_.push_back(std::move(rec));
        }
        rtcCommitGeometry(g);
        sphereGeometry_ = rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        checkDevice(device_, "adding spheres");
    }
    rtcCommitScene(scene_);
    checkDevice(device_, "building the BVH");
}

SceneGeometry::~SceneGeometry() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

bool SceneGeometry::intersect(Vec3f o, Vec3f d, float tMax, Intersection& out) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = o.x; rh.ray.org_y = o.y; rh.ray.org_z = o.z;
    rh.ray.dir_x = d.x; rh.ray.dir_y = d.y; rh.ray.dir_z = d.z;
    rh.ray.tnear = 0;
    rh.ray.tfar = tMax;
    rh.ray.time = 0;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

    out.t = rh.ray.tfar;
    SurfaceHit& h = out.hit;
    h.p = o + out.t * d;
    if (rh.hit.geomID == sphereGeometry_) {
        const SphereRecord& s = spheres_[rh.hit.primID];
        h.ng = normalize(h.p - s.sphere.centre);
        if (s.sphere.flipNormals) h.ng = -h.ng;
        h.ns = h.ng;
        // pbrt's sphere (u, v): the azimuth and polar angle in the sphere's object space.
        const Vec3f q = normalize(transformVector(inverse(s.sphere.objectToWorld), h.p - s.sphere.centre));
        float phi = std::atan2(q.y, q.x);
        if (phi < 0) phi += 2.0f * float(M_PI);
        h.u = phi / (2.0f * float(M_PI));
        h.v = 1.0f - std::acos(std::clamp(q.z, -1.0f, 1.0f)) / float(M_PI);
        out.material = s.sphere.material.get();
        out.light = s.light;
        return true;
    }
    const MeshRecord& rec = meshes_[rh.hit.geomID];
    const TriangleMesh& m = rec.mesh;
    const std::uint32_t prim = rh.hit.primID;
    const std::uint32_t i0 = m.indices[3 * prim], i1 = m.indices[3 * prim + 1], i2 = m.indices[3 * prim + 2];
    const float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
    h.ng = orientedFaceNormal(m, prim);
    h.ns = h.ng;
    if (!m.n.empty()) {
        const Vec3f ns = b0 * m.n[i0] + b1 * m.n[i1] + b2 * m.n[i2];
        const float len = length(ns);
        if (len > 0) h.ns = dot(ns, h.ng) >= 0 ? ns / len : -ns / len;
    }
    if (!m.uv.empty()) {
        h.u = b0 * m.uv[2 * i0] + b1 * m.uv[2 * i1] + b2 * m.uv[2 * i2];
        h.v = b0 * m.uv[2 * i0 + 1] + b1 * m.uv[2 * i1 + 1] + b2 * m.uv[2 * i2 + 1];
    } else {  // pbrt's default per-triangle (0,0), (1,0), (1,1)
        h.u = b1 + b2;
        h.v = b2;
    }
    out.material = m.material.get();
    out.light = rec.triangleLights.empty() ? nullptr : rec.triangleLights[prim];
    return true;
}

bool SceneGeometry::occluded(Vec3f o, Vec3f d, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    r.org_x = o.x; r.org_y = o.y; r.org_z = o.z;
    r.dir_x = d.x; r.dir_y = d.y; r.dir_z = d.z;
    r.tnear = 0;
    r.tfar = tMax;
    r.time = 0;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
    rtcOccluded1(scene_, &context, &r);
    return r.tfar < 0;  // Embree sets tfar to -inf on a hit
}

}  // namespace lenslab
