#pragma once
// pbrt-v3's quadrics (sphere, disk, cylinder, cone, paraboloid, hyperboloid) as Embree user
// geometries. Each is defined in its own object space about the z axis, possibly cut by phimax
// and a z range; rays are intersected there in double precision, so any invertible transform
// (non-uniform scale and shear included) keeps the surface exact, and the inside shows through
// the cut. One quadric is one primitive for area lights, sampled over the partial surface.
#include <memory>

#include "shapes/Shape.h"

namespace lenslab {

struct Vec3d {
    double x = 0, y = 0, z = 0;
};
inline Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3d operator*(double s, Vec3d a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The azimuth of (x, y) in [0, 2 pi), as pbrt-v3 measures phi.
double azimuth(double x, double y);

class Quadric : public Shape {
public:
    Quadric(const Transform& objectToGroup, bool reverseOrientation, double phiMaxDegrees);

    unsigned attach(RTCDevice device, RTCScene scene) const override;
    void surface(Vec3f o, Vec3f d, float t, unsigned prim, float hitU, float hitV, SurfaceHit& out) const override;
    std::size_t primitiveCount() const override { return 1; }
    float primitiveArea(std::size_t) const override { return float(groupArea_); }
    ShapeSample samplePrimitive(std::size_t prim, float u1, float u2) const override;
    float primitivePdf(std::size_t prim, const SurfaceHit& at) const override;

    // The nearest hit in (tMin, tMax) of the group-space ray (o, d); false when none.
    bool intersectGroupRay(Vec3f o, Vec3f d, float tMin, float tMax, float& t) const;
    const RTCBounds& groupBounds() const { return groupBounds_; }
    // Object space: the surface area and pbrt-v3's (u, v) at a point on it.
    virtual double objectArea() const = 0;
    virtual void uv(Vec3d p, double& u, double& v) const = 0;
    // Measures the area in the group's space; every factory calls it once the shape is complete.
    void measure();

protected:
    // Object-space pieces a quadric supplies: the nearest hit in (tMin, tMax) of the ray (o, d)
    // (quadrics of revolution pass their a t^2 + b t + c = 0 to nearestRoot).
    virtual bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const = 0;
    virtual Vec3d refine(Vec3d p) const { return p; }  // back onto the surface against rounding
    virtual bool accepts(Vec3d p) const = 0;           // inside the z range and phimax
    virtual Vec3d normal(Vec3d p) const = 0;           // along dp/du x dp/dv, any length
    // pbrt-v3's dp/du and dp/dv at a point of the surface, of its own (u, v).
    virtual void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const = 0;
    // pbrt-v3's second partials d2p/du2, d2p/du dv and d2p/dv2 there, for the normal's turning.
    virtual void secondPartials(Vec3d p, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const = 0;
    virtual void bounds(Vec3d& lo, Vec3d& hi) const = 0;
    // A point drawn over the object-space surface, and its density per unit object-space area
    // (uniform unless a quadric says otherwise).
    virtual Vec3d sample(double u1, double u2) const = 0;
    virtual double objectPdf(Vec3d) const { return 1.0 / objectArea(); }

    // The linear scale of objectToGroup when it is a similarity (a rotation, mirror and one scale
    // factor: areas scale by one constant), else 0; and an object-space point in the group's space.
    double similarityScale() const { return similarityScale_; }
    Vec3f toGroup(Vec3d p) const;
    // dp/du of the azimuthal u = phi / phimax that every quadric has.
    Vec3d azimuthalPartial(Vec3d p) const { return {-phiMax_ * p.y, phiMax_ * p.x, 0}; }
    // Its d2p/du2, the same for every quadric of revolution.
    Vec3d azimuthalSecondPartial(Vec3d p) const { return {-phiMax_ * phiMax_ * p.x, -phiMax_ * phiMax_ * p.y, 0}; }

    // The nearest root of a t^2 + b t + c = 0 in (tMin, tMax) whose point passes accepts().
    bool nearestRoot(double a, double b, double c, Vec3d o, Vec3d d, double tMin, double tMax, double& t) const;

    double phiMax_;  // radians

private:
    Vec3d toObject(Vec3f p) const;
    Vec3d toObjectVector(Vec3f v) const;
    Vec3f groupNormal(Vec3d pObject, double& areaScale) const;
    void groupNormalPartials(Vec3d pObject, Vec3d dpdu, Vec3d dpdv, Vec3f& dndu, Vec3f& dndv) const;

    Transform objectToGroup_;
    float flip_;               // -1: ReverseOrientation xor a handedness swap
    double similarityScale_;
    double groupArea_ = 0;
    RTCBounds groupBounds_{};
};

// pbrt-v3's quadric shapes with their parameters and defaults. Throw SceneError through
// params.fail for values that describe no surface.
std::shared_ptr<const Shape> makeSphere(const ParamSet& params, const Transform& objectToGroup, bool reverseOrientation);
std::shared_ptr<const Shape> makeDisk(const ParamSet& params, const Transform& objectToGroup, bool reverseOrientation);
std::shared_ptr<const Shape> makeCylinder(const ParamSet& params, const Transform& objectToGroup, bool reverseOrientation);
std::shared_ptr<const Shape> makeCone(const ParamSet& params, const Transform& objectToGroup, bool reverseOrientation);
std::shared_ptr<const Shape> makeParaboloid(const ParamSet& params, const Transform& objectToGroup, bool reverseOrientation);
std::shared_ptr<const Shape> makeHyperboloid(const ParamSet& params, const Transform& objectToGroup, bool reverseOrientation);

}  // namespace lenslab
