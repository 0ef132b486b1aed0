// pbrt-v3's sphere: radius, cut to [zmin, zmax] and phi <= phimax. u = phi / phimax; v runs with
// the polar angle from 0 at zmin to 1 at zmax.
#include <algorithm>
#include <cmath>

#include "shapes/Quadric.h"

namespace lenslab {

namespace {

class Sphere : public Quadric {
public:
    Sphere(double r, double z0, double z1, double phiMax, const Transform& toGroup, bool ro)
        : Quadric(toGroup, ro, phiMax), r_(r), zMin_(std::clamp(std::min(z0, z1), -r, r)),
          zMax_(std::clamp(std::max(z0, z1), -r, r)), thetaZMin_(std::acos(zMin_ / r)), thetaZMax_(std::acos(zMax_ / r)) {}

    std::optional<EmbreeSphere> embreeSphere() const override {
        if (!(similarityScale() > 0 && zMin_ <= -r_ && zMax_ >= r_ && phiMax_ >= 2 * M_PI)) return std::nullopt;
        return EmbreeSphere{toGroup({0, 0, 0}), float(r_ * similarityScale())};
    }

    double objectArea() const override { return phiMax_ * r_ * (zMax_ - zMin_); }
    void uv(Vec3d p, double& u, double& v) const override {
        u = azimuth(p.x, p.y) / phiMax_;
        v = (std::acos(std::clamp(p.z / r_, -1.0, 1.0)) - thetaZMin_) / (thetaZMax_ - thetaZMin_);
    }

protected:
    bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const override {
        return nearestRoot(dot(d, d), 2 * dot(d, o), dot(o, o) - r_ * r_, o, d, tMin, tMax, t);
    }
    Vec3d refine(Vec3d p) const override {
        p = (r_ / std::sqrt(dot(p, p))) * p;
        // phi and the partials are defined everywhere: points within rounding of the axis (a rotated
        // sphere's pole has x, y ~ 1e-32) are nudged off it.
        if (std::hypot(p.x, p.y) < 1e-9 * r_) p.x = 1e-5 * r_;
        return p;
    }
    bool accepts(Vec3d p) const override {
        // The z tests only for a cut sphere: rounding at the poles must not punch holes.
        return !((zMin_ > -r_ && p.z < zMin_) || (zMax_ < r_ && p.z > zMax_) || azimuth(p.x, p.y) > phiMax_);
    }
    Vec3d normal(Vec3d p) const override { return p; }
    void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const override {
        // r sin(theta) taken as rho, so that dp/dv stays tangent at refine's nudged poles too.
        const double rho = std::hypot(p.x, p.y), dTheta = thetaZMax_ - thetaZMin_;
        dpdu = azimuthalPartial(p);
        dpdv = dTheta * Vec3d{p.z * p.x / rho, p.z * p.y / rho, -rho};
    }
    void secondPartials(Vec3d p, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const override {
        const double rho = std::hypot(p.x, p.y), dTheta = thetaZMax_ - thetaZMin_;
        duu = azimuthalSecondPartial(p);
        duv = (dTheta * phiMax_ * p.z / rho) * Vec3d{-p.y, p.x, 0};
        dvv = (-dTheta * dTheta) * p;
    }
    void bounds(Vec3d& lo, Vec3d& hi) const override {
        lo = {-r_, -r_, zMin_};
        hi = {r_, r_, zMax_};
    }
    // Archimedes: area is uniform in z.
    Vec3d sample(double u1, double u2) const override {
        const double z = zMin_ + u1 * (zMax_ - zMin_), phi = u2 * phiMax_;
        const double rho = std::sqrt(std::max(0.0, r_ * r_ - z * z));
        return {rho * std::cos(phi), rho * std::sin(phi), z};
    }

private:
    double r_, zMin_, zMax_, thetaZMin_, thetaZMax_;
};

}  // namespace

std::shared_ptr<const Shape> makeSphere(const ParamSet& p, const Transform& toGroup, bool ro) {
    const double r = p.getFloat("radius", 1);
    if (!(r > 0)) p.fail("radius must be positive");
    const double zMin = p.getFloat("zmin", -r), zMax = p.getFloat("zmax", r), phiMax = p.getFloat("phimax", 360);
    if (!(std::min(zMax, r) > std::max(zMin, -r))) p.fail("zmin and zmax leave no part of the sphere");
    if (!(phiMax > 0)) p.fail("phimax must be positive");
    auto s = std::make_shared<Sphere>(r, zMin, zMax, phiMax, toGroup, ro);
    s->measure();
    return s;
}

}  // namespace lenslab
