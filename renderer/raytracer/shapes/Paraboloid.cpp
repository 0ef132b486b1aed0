// pbrt-v3's paraboloid z = zmax (x^2 + y^2) / radius^2, cut to [zmin, zmax] and phi <= phimax.
// u = phi / phimax, v = (z - zmin) / (zmax - zmin).
#include <algorithm>
#include <cmath>

#include "shapes/Quadric.h"

namespace lenslab {

namespace {

class Paraboloid : public Quadric {
public:
    Paraboloid(double r, double z0, double z1, double phiMax, const Transform& toGroup, bool ro)
        : Quadric(toGroup, ro, phiMax), r_(r), zMin_(std::max(0.0, std::min(z0, z1))), zMax_(std::max(z0, z1)),
          k_(zMax_ / (r * r)) {}

    // With rho^2 = z / k the area element is rho sqrt(1 + 4 k^2 rho^2) drho dphi, whose integral is
    // (1 + 4 k z)^(3/2) / (12 k^2): uniform in that power is uniform by area.
    double objectArea() const override { return phiMax_ * (growth(zMax_) - growth(zMin_)) / (12 * k_ * k_); }
    void uv(Vec3d p, double& u, double& v) const override {
        u = azimuth(p.x, p.y) / phiMax_;
        v = (p.z - zMin_) / (zMax_ - zMin_);
    }

protected:
    bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const override {
        return nearestRoot(k_ * (d.x * d.x + d.y * d.y), 2 * k_ * (d.x * o.x + d.y * o.y) - d.z,
                           k_ * (o.x * o.x + o.y * o.y) - o.z, o, d, tMin, tMax, t);
    }
    bool accepts(Vec3d p) const override { return p.z >= zMin_ && p.z <= zMax_ && azimuth(p.x, p.y) <= phiMax_; }
    Vec3d normal(Vec3d p) const override { return {2 * k_ * p.x, 2 * k_ * p.y, -1}; }
    // dp/dv grows without bound at the vertex (z = 0), where it is taken a hair above.
    void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const override {
        const double z = std::max(p.z, 1e-9 * zMax_);
        dpdu = azimuthalPartial(p);
        dpdv = (zMax_ - zMin_) * Vec3d{p.x / (2 * z), p.y / (2 * z), 1};
    }
    void secondPartials(Vec3d p, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const override {
        const double z = std::max(p.z, 1e-9 * zMax_), dz = zMax_ - zMin_;
        duu = azimuthalSecondPartial(p);
        duv = (dz * phiMax_ / (2 * z)) * Vec3d{-p.y, p.x, 0};
        dvv = (-dz * dz / (4 * z * z)) * Vec3d{p.x, p.y, 0};
    }
    void bounds(Vec3d& lo, Vec3d& hi) const override {
        lo = {-r_, -r_, zMin_};
        hi = {r_, r_, zMax_};
    }
    Vec3d sample(double u1, double u2) const override {
        const double g = growth(zMin_) + u1 * (growth(zMax_) - growth(zMin_));
        const double z = std::max(0.0, (std::cbrt(g * g) - 1) / (4 * k_)), rho = std::sqrt(z / k_), phi = u2 * phiMax_;
        return {rho * std::cos(phi), rho * std::sin(phi), z};
    }

private:
    double growth(double z) const { return std::pow(1 + 4 * k_ * z, 1.5); }

    double r_, zMin_, zMax_, k_;
};

}  // namespace

std::shared_ptr<const Shape> makeParaboloid(const ParamSet& p, const Transform& toGroup, bool ro) {
    const double r = p.getFloat("radius", 1), zMin = p.getFloat("zmin", 0), zMax = p.getFloat("zmax", 1);
    const double phiMax = p.getFloat("phimax", 360);
    if (!(r > 0)) p.fail("radius must be positive");
    if (!(std::max(zMin, zMax) > std::max(0.0, std::min(zMin, zMax)))) p.fail("zmin and zmax leave no part above z = 0");
    if (!(phiMax > 0)) p.fail("phimax must be positive");
    auto s = std::make_shared<Paraboloid>(r, zMin, zMax, phiMax, toGroup, ro);
    s->measure();
    return s;
}

}  // namespace lenslab
