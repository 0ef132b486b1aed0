// pbrt-v3's cone: base of radius at z = 0, apex at z = height, phi <= phimax. u = phi / phimax,
// v = z / height.
#include <cmath>

#include "shapes/Quadric.h"

namespace lenslab {

namespace {

class Cone : public Quadric {
public:
    Cone(double h, double r, double phiMax, const Transform& toGroup, bool ro)
        : Quadric(toGroup, ro, phiMax), h_(h), r_(r), k_((r / h) * (r / h)) {}

    double objectArea() const override { return 0.5 * r_ * std::sqrt(h_ * h_ + r_ * r_) * phiMax_; }
    void uv(Vec3d p, double& u, double& v) const override {
        u = azimuth(p.x, p.y) / phiMax_;
        v = p.z / h_;
    }

protected:
    // x^2 + y^2 = k (z - h)^2
    bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const override {
        const double oz = o.z - h_;
        return nearestRoot(d.x * d.x + d.y * d.y - k_ * d.z * d.z, 2 * (d.x * o.x + d.y * o.y - k_ * d.z * oz),
                           o.x * o.x + o.y * o.y - k_ * oz * oz, o, d, tMin, tMax, t);
    }
    bool accepts(Vec3d p) const override { return p.z >= 0 && p.z <= h_ && azimuth(p.x, p.y) <= phiMax_; }
    Vec3d normal(Vec3d p) const override { return {p.x, p.y, -k_ * (p.z - h_)}; }
    // pbrt-v3's (-x / (1 - v), -y / (1 - v), height), by the azimuth so that the apex has it too.
    void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const override {
        const double phi = azimuth(p.x, p.y);
        dpdu = azimuthalPartial(p);
        dpdv = {-r_ * std::cos(phi), -r_ * std::sin(phi), h_};
    }
    // pbrt-v3's d2p/du dv = phimax (y, -x, 0) / (1 - v), again by the azimuth.
    void secondPartials(Vec3d p, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const override {
        const double phi = azimuth(p.x, p.y);
        duu = azimuthalSecondPartial(p);
        duv = (phiMax_ * r_) * Vec3d{std::sin(phi), -std::cos(phi), 0};
        dvv = {};
    }
    void bounds(Vec3d& lo, Vec3d& hi) const override {
        lo = {-r_, -r_, 0};
        hi = {r_, r_, h_};
    }
    // Area grows with the radius, 1 - v: 1 - v = sqrt(1 - u1) is uniform by area.
    Vec3d sample(double u1, double u2) const override {
        const double w = std::sqrt(1 - u1), phi = u2 * phiMax_;
        return {r_ * w * std::cos(phi), r_ * w * std::sin(phi), h_ * (1 - w)};
    }

private:
    double h_, r_, k_;
};

}  // namespace

std::shared_ptr<const Shape> makeCone(const ParamSet& p, const Transform& toGroup, bool ro) {
    const double h = p.getFloat("height", 1), r = p.getFloat("radius", 1), phiMax = p.getFloat("phimax", 360);
    if (!(h > 0) || !(r > 0)) p.fail("height and radius must be positive");
    if (!(phiMax > 0)) p.fail("phimax must be positive");
    auto s = std::make_shared<Cone>(h, r, phiMax, toGroup, ro);
    s->measure();
    return s;
}

}  // namespace lenslab
