#include "SceneGeometry.h"

#include <cmath>
#include <string>

#include "AreaLight.h"
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

// Embree's instance transform: the affine 3x4 part, column by column.
void attachInstance(RTCDevice device, RTCScene world, RTCScene object, const Transform& toWorld) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, object);
    float m[12];
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 3; ++row) m[3 * col + row] = float(toWorld.forward.m[row][col]);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
    rtcCommitGeometry(g);
    rtcAttachGeometry(world, g);
    rtcReleaseGeometry(g);
}

}  // namespace

SceneGeometry::ObjectScene SceneGeometry::buildObject(const ObjectDefinition& object) {
    ObjectScene o;
    o.scene = newScene(device_);
    for (const ShapeEntry& e : object.shapes) {
        if (e.shape->attach(device_, o.scene) != o.shapes.size()) throw SceneError("Embree: unexpected geometry id");
        o.shapes.push_back(&e);
    }
    rtcCommitScene(o.scene);
    return o;
}

SceneGeometry::SceneGeometry(SceneDescription& scene)
    : shapes_(std::move(scene.shapes)), objects_(std::move(scene.objects)), instances_(std::move(scene.instances)),
      lights_(std::move(scene.lights)) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw SceneError("Embree: cannot create a device");

    for (const ObjectDefinition& object : objects_) objectScenes_.push_back(buildObject(object));
    checkDevice(device_, "building instanced objects");

    scene_ = newScene(device_);
    for (const ShapeEntry& e : shapes_) {
        const unsigned id = e.shape->attach(device_, scene_);
        if (id != world_.size()) throw SceneError("Embree: unexpected geometry id");
        WorldSlot slot;
        slot.shape = &e;
        if (e.emission) {
            slot.emits = true;
            slot.firstLight = lights_.size();
            for (std::size_t prim = 0; prim < e.shape->primitiveCount(); ++prim)
                lights_.push_back(makeDiffuseAreaLight(e.shape, prim, e.emission->L, e.emission->twoSided));
        }
        world_.push_back(slot);
    }
    for (const ObjectInstance& inst : instances_) {
        if (objects_[inst.object].shapes.empty()) continue;
        attachInstance(device_, scene_, objectScenes_[inst.object].scene, inst.instanceToWorld);
        WorldSlot slot;
        slot.instance = &inst;
        world_.push_back(slot);
    }
    rtcCommitScene(scene_);
    checkDevice(device_, "building the BVH");

    RTCBounds b;
    rtcGetSceneBounds(scene_, &b);
    const Vec3f lo{b.lower_x, b.lower_y, b.lower_z}, hi{b.upper_x, b.upper_y, b.upper_z};
    const bool empty = !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z);
    for (auto& light : lights_) light->setSceneBounds(empty ? Vec3f{} : 0.5f * (lo + hi), empty ? 0.0f : 0.5f * length(hi - lo));
}

SceneGeometry::~SceneGeometry() {
    if (scene_) rtcReleaseScene(scene_);
    for (ObjectScene& o : objectScenes_) rtcReleaseScene(o.scene);
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
    out.light = nullptr;
    SurfaceHit& h = out.hit;
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        // Shapes inside an object answer in the object's space; bring the hit back to the world
        // (normals by the inverse transpose, as pbrt-v3's TransformedPrimitive).
        const ObjectInstance& inst = *world_[rh.hit.instID[0]].instance;
        const Transform toObject = inverse(inst.instanceToWorld);
        const ShapeEntry& e = *objectScenes_[inst.object].shapes[rh.hit.geomID];
        e.shape->surface(transformPoint(toObject, o), transformVector(toObject, d), out.t, rh.hit.primID, rh.hit.u,
                         rh.hit.v, h);
        h.p = transformPoint(inst.instanceToWorld, h.p);
        h.ng = normalize(transformNormal(inst.instanceToWorld, h.ng));
        h.ns = normalize(transformNormal(inst.instanceToWorld, h.ns));
        out.material = e.material.get();
        return true;
    }
    const WorldSlot& slot = world_[rh.hit.geomID];
    slot.shape->shape->surface(o, d, out.t, rh.hit.primID, rh.hit.u, rh.hit.v, h);
    out.material = slot.shape->material.get();
    if (slot.emits) out.light = lights_[slot.firstLight + rh.hit.primID].get();
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
