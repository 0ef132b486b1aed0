// pbrt-v3's cylinder: radius about the z axis from zmin to zmax, phi <= phimax. u = phi / phimax,
// v = (z - zmin) / (zmax - zmin).
#include <algorithm>
#include <cmath>

#include "shapes/Quadric.h"

namespace lenslab {

namespace {

class Cylinder : public Quadric {
public:
    Cylinder(double r, double z0, double z1, double phiMax, const Transform& toGroup, bool ro)
        : Quadric(toGroup, ro, phiMax), r_(r), zMin_(std::min(z0, z1)), zMax_(std::max(z0, z1)) {}

    double objectArea() const override { return (zMax_ - zMin_) * r_ * phiMax_; }
    void uv(Vec3d p, double& u, double& v) const override {
        u = azimuth(p.x, p.y) / phiMax_;
        v = (p.z - zMin_) / (zMax_ - zMin_);
    }

protected:
    bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const override {
        return nearestRoot(d.x * d.x + d.y * d.y, 2 * (d.x * o.x + d.y * o.y), o.x * o.x + o.y * o.y - r_ * r_, o, d,
                           tMin, tMax, t);
    }
    Vec3d refine(Vec3d p) const override {
        const double s = r_ / std::hypot(p.x, p.y);
        return {s * p.x, s * p.y, p.z};
    }
    bool accepts(Vec3d p) const override { return p.z >= zMin_ && p.z <= zMax_ && azimuth(p.x, p.y) <= phiMax_; }
    Vec3d normal(Vec3d p) const override { return {p.x, p.y, 0}; }
    void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const override {
        dpdu = azimuthalPartial(p);
        dpdv = {0, 0, zMax_ - zMin_};
    }
    void secondPartials(Vec3d p, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const override {
        duu = azimuthalSecondPartial(p);
        duv = dvv = {};
    }
    void bounds(Vec3d& lo, Vec3d& hi) const override {
        lo = {-r_, -r_, zMin_};
        hi = {r_, r_, zMax_};
    }
    Vec3d sample(double u1, double u2) const override {
        const double phi = u2 * phiMax_;
        return {r_ * std::cos(phi), r_ * std::sin(phi), zMin_ + u1 * (zMax_ - zMin_)};
    }

private:
    double r_, zMin_, zMax_;
};

}  // namespace

std::shared_ptr<const Shape> makeCylinder(const ParamSet& p, const Transform& toGroup, bool ro) {
    const double r = p.getFloat("radius", 1), zMin = p.getFloat("zmin", -1), zMax = p.getFloat("zmax", 1);
    const double phiMax = p.getFloat("phimax", 360);
    if (!(r > 0)) p.fail("radius must be positive");
    if (!(zMin != zMax)) p.fail("zmin and zmax must differ");
    if (!(phiMax > 0)) p.fail("phimax must be positive");
    auto s = std::make_shared<Cylinder>(r, zMin, zMax, phiMax, toGroup, ro);
    s->measure();
    return s;
}

}  // namespace lenslab
