#include "geometry/SceneGeometry.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lights/AreaLight.h"
#include "Render.h"

namespace lenslab {

namespace {

void checkDevice(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw SceneError(std::string("Embree failed ") + what + " (error " + std::to_string(int(e)) + ")");
}

RTCScene newScene(RTCDevice device) {
    RTCScene s = rtcNewScene(device);
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    return s;
}

static_assert(sizeof(EmbreeSphere) == 4 * sizeof(float), "Embree reads spheres as x, y, z, radius");

// A keyframe as Embree's quaternion decomposition (T R S, S upper triangular; no shift).
RTCQuaternionDecomposition embreeParts(const TransformParts& p) {
    RTCQuaternionDecomposition q;
    rtcInitQuaternionDecomposition(&q);
    rtcQuaternionDecompositionSetScale(&q, float(p.stretch[0][0]), float(p.stretch[1][1]), float(p.stretch[2][2]));
    rtcQuaternionDecompositionSetSkew(&q, float(p.stretch[0][1]), float(p.stretch[0][2]), float(p.stretch[1][2]));
    const Quaternion& r = p.rotation;
    rtcQuaternionDecompositionSetQuaternion(&q, float(r.r), float(r.i), float(r.j), float(r.k));
    rtcQuaternionDecompositionSetTranslation(&q, float(p.translation[0]), float(p.translation[1]), float(p.translation[2]));
    return q;
}

// A still instance takes Embree's affine 3x4 matrix, column by column; a moving one its time steps,
// which Embree blends as AnimatedTransform::at does.
unsigned attachInstance(RTCDevice device, RTCScene world, RTCScene object, const AnimatedTransform& toWorld) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, object);
    if (toWorld.moves()) {
        const std::vector<TransformParts>& steps = toWorld.steps();
        rtcSetGeometryTimeStepCount(g, unsigned(steps.size()));
        for (std::size_t i = 0; i < steps.size(); ++i) {
            const RTCQuaternionDecomposition q = embreeParts(steps[i]);
            rtcSetGeometryTransformQuaternion(g, unsigned(i), &q);
        }
    } else {
        float m[12];
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 3; ++row) m[3 * col + row] = float(toWorld.start().forward.m[row][col]);
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
    }
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(world, g);
    rtcReleaseGeometry(g);
    return id;
}

}  // namespace

SceneGeometry::Group SceneGeometry::buildGroup(const std::vector<ShapeEntry>& shapes) {
    Group g;
    g.scene = newScene(device_);
    std::vector<EmbreeSphere> spheres;
    for (const ShapeEntry& e : shapes) {
        if (const auto sphere = e.shape->embreeSphere()) {
            spheres.push_back(*sphere);
            g.spheres.push_back(&e);
            continue;
        }
        if (e.shape->attach(device_, g.scene) != g.byGeometry.size()) throw SceneError("Embree: unexpected geometry id");
        g.byGeometry.push_back(&e);
    }
    if (!spheres.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<EmbreeSphere*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                                     sizeof(EmbreeSphere), spheres.size()));
        if (v) std::copy(spheres.begin(), spheres.end(), v);
        rtcCommitGeometry(geometry);
        g.sphereBatch = rtcAttachGeometry(g.scene, geometry);
        rtcReleaseGeometry(geometry);
        g.byGeometry.push_back(nullptr);
    }
    g.instances.assign(g.byGeometry.size(), nullptr);
    return g;
}

SceneGeometry::SceneGeometry(SceneDescription& scene)
    : shapes_(std::move(scene.shapes)), objects_(std::move(scene.objects)), instances_(std::move(scene.instances)),
      lights_(std::move(scene.lights)) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw SceneError("Embree: cannot create a device");

    for (const ObjectDefinition& object : objects_) {
        objectGroups_.push_back(buildGroup(object.shapes));
        rtcCommitScene(objectGroups_.back().scene);
    }
    checkDevice(device_, "building instanced objects");

    world_ = buildGroup(shapes_);
    for (const ObjectInstance& inst : instances_) {
        if (objects_[inst.object].shapes.empty()) continue;
        if (attachInstance(device_, world_.scene, objectGroups_[inst.object].scene, inst.instanceToWorld) !=
            world_.byGeometry.size())
            throw SceneError("Embree: unexpected geometry id");
        world_.byGeometry.push_back(nullptr);
        world_.instances.push_back(&inst);
    }
    rtcCommitScene(world_.scene);
    checkDevice(device_, "building the BVH");

    for (const ShapeEntry& e : shapes_) {
        firstLight_.push_back(lights_.size());
        if (!e.emission) continue;
        for (std::size_t prim = 0; prim < e.shape->primitiveCount(); ++prim)
            lights_.push_back(makeDiffuseAreaLight(e.shape, prim, e.emission->L, e.emission->twoSided));
    }
    const auto passthrough = [](const std::vector<ShapeEntry>& shapes) {
        return std::any_of(shapes.begin(), shapes.end(), [](const ShapeEntry& e) { return e.material->isPassthrough(); });
    };
    hasPassthrough_ = passthrough(shapes_) ||
                      std::any_of(objects_.begin(), objects_.end(), [&](const ObjectDefinition& o) { return passthrough(o.shapes); });
    RTCBounds b;
    rtcGetSceneBounds(world_.scene, &b);
    const Vec3f lo{b.lower_x, b.lower_y, b.lower_z}, hi{b.upper_x, b.upper_y, b.upper_z};
    const bool empty = !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z);
    for (auto& light : lights_) light->setSceneBounds(empty ? Vec3f{} : 0.5f * (lo + hi), empty ? 0.0f : 0.5f * length(hi - lo));
}

SceneGeometry::~SceneGeometry() {
    if (world_.scene) rtcReleaseScene(world_.scene);
    for (Group& g : objectGroups_) rtcReleaseScene(g.scene);
    if (device_) rtcReleaseDevice(device_);
}

const ShapeEntry& SceneGeometry::hitShape(const Group& group, unsigned geomID, unsigned& prim) {
    if (geomID != group.sphereBatch) return *group.byGeometry[geomID];
    const ShapeEntry& e = *group.spheres[prim];
    prim = 0;
    return e;
}

bool SceneGeometry::intersect(Vec3f o, Vec3f d, float tMax, float time, Intersection& out) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = o.x; rh.ray.org_y = o.y; rh.ray.org_z = o.z;
    rh.ray.dir_x = d.x; rh.ray.dir_y = d.y; rh.ray.dir_z = d.z;
    rh.ray.tnear = 0;
    rh.ray.tfar = tMax;
    rh.ray.time = time;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(world_.scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

    out.t = rh.ray.tfar;
    out.time = time;
    out.light = nullptr;
    SurfaceHit& h = out.hit;
    unsigned prim = rh.hit.primID;
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        // Shapes inside an object answer in the object's space; bring the hit back to the world
        // (normals by the inverse transpose, as pbrt-v3's TransformedPrimitive).
        const ObjectInstance& inst = *world_.instances[rh.hit.instID[0]];
        const Transform toWorld = inst.instanceToWorld.at(time), toObject = inverse(toWorld);
        const ShapeEntry& e = hitShape(objectGroups_[inst.object], rh.hit.geomID, prim);
        e.shape->surface(transformPoint(toObject, o), transformVector(toObject, d), out.t, prim, rh.hit.u, rh.hit.v, h);
        h.p = transformPoint(toWorld, h.p);
        h.ng = normalize(transformNormal(toWorld, h.ng));
        h.dndu = transformNormalPartial(toWorld, h.ns, h.dndu);
        h.dndv = transformNormalPartial(toWorld, h.ns, h.dndv);
        h.ns = normalize(transformNormal(toWorld, h.ns));
        h.dpdu = transformVector(toWorld, h.dpdu);
        h.dpdv = transformVector(toWorld, h.dpdv);
        out.material = e.material.get();
        out.media = &e.media;
        out.material->applyBump(h);
        return true;
    }
    const ShapeEntry& e = hitShape(world_, rh.hit.geomID, prim);
    e.shape->surface(o, d, out.t, prim, rh.hit.u, rh.hit.v, h);
    out.material = e.material.get();
    out.media = &e.media;
    out.material->applyBump(h);
    if (e.emission) out.light = lights_[firstLight_[std::size_t(&e - shapes_.data())] + prim].get();
    return true;
}

bool SceneGeometry::occluded(Vec3f o, Vec3f d, float tMax, float time) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    r.org_x = o.x; r.org_y = o.y; r.org_z = o.z;
    r.dir_x = d.x; r.dir_y = d.y; r.dir_z = d.z;
    r.tnear = 0;
    r.tfar = tMax;
    r.time = time;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
    rtcOccluded1(world_.scene, &context, &r);
    return r.tfar < 0;  // Embree sets tfar to -inf on a hit
}

}  // namespace lenslab
