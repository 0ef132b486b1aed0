// pbrt-v3's disk: the annulus innerradius <= rho <= radius in the plane z = height, phi <= phimax,
// facing +z. u = phi / phimax, v = (radius - rho) / (radius - innerradius).
#include <algorithm>
#include <cmath>

#include "shapes/Quadric.h"

namespace lenslab {

namespace {

class Disk : public Quadric {
public:
    Disk(double h, double r, double ri, double phiMax, const Transform& toGroup, bool ro)
        : Quadric(toGroup, ro, phiMax), h_(h), r_(r), ri_(ri) {}

    double objectArea() const override { return 0.5 * phiMax_ * (r_ * r_ - ri_ * ri_); }
    void uv(Vec3d p, double& u, double& v) const override {
        u = azimuth(p.x, p.y) / phiMax_;
        v = (r_ - std::hypot(p.x, p.y)) / (r_ - ri_);
    }

protected:
    bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const override {
        if (d.z == 0) return false;
        const double th = (h_ - o.z) / d.z;
        if (!(th > tMin && th < tMax) || !accepts(refine(o + th * d))) return false;
        t = th;
        return true;
    }
    Vec3d refine(Vec3d p) const override { return {p.x, p.y, h_}; }
    bool accepts(Vec3d p) const override {
        const double rho2 = p.x * p.x + p.y * p.y;
        return rho2 <= r_ * r_ && rho2 >= ri_ * ri_ && azimuth(p.x, p.y) <= phiMax_;
    }
    Vec3d normal(Vec3d) const override { return {0, 0, 1}; }
    void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const override {
        const double phi = azimuth(p.x, p.y);  // not p / rho: defined at the centre too
        dpdu = azimuthalPartial(p);
        dpdv = (ri_ - r_) * Vec3d{std::cos(phi), std::sin(phi), 0};
    }
    // The plane's normal never turns; pbrt-v3 gives the disk no dn/du and dn/dv either.
    void secondPartials(Vec3d, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const override { duu = duv = dvv = {}; }
    void bounds(Vec3d& lo, Vec3d& hi) const override {
        lo = {-r_, -r_, h_};
        hi = {r_, r_, h_};
    }
    Vec3d sample(double u1, double u2) const override {  // uniform in rho^2
        const double rho = std::sqrt(ri_ * ri_ + u1 * (r_ * r_ - ri_ * ri_)), phi = u2 * phiMax_;
        return {rho * std::cos(phi), rho * std::sin(phi), h_};
    }

private:
    double h_, r_, ri_;
};

}  // namespace

std::shared_ptr<const Shape> makeDisk(const ParamSet& p, const Transform& toGroup, bool ro) {
    const double h = p.getFloat("height", 0), r = p.getFloat("radius", 1), ri = p.getFloat("innerradius", 0);
    const double phiMax = p.getFloat("phimax", 360);
    if (!(r > 0)) p.fail("radius must be positive");
    if (!(ri >= 0 && ri < r)) p.fail("innerradius must lie in [0, radius)");
    if (!(phiMax > 0)) p.fail("phimax must be positive");
    auto s = std::make_shared<Disk>(h, r, ri, phiMax, toGroup, ro);
    s->measure();
    return s;
}

}  // namespace lenslab
