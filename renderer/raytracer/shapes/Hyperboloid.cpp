// pbrt-v3's hyperboloid: the surface of revolution ah (x^2 + y^2) - ch z^2 = 1 that pbrt-v3 fits
// through the segment p1-p2, cut to the segment's z range and phi <= phimax, with phi measured from
// the segment's point at the same height. v = (z - p1.z) / (p2.z - p1.z), u = phi / phimax.
#include <algorithm>
#include <array>
#include <cmath>

#include "shapes/Quadric.h"

namespace lenslab {

namespace {

constexpr int kAreaBins = 64;  // the area-sampling histogram over z

class Hyperboloid : public Quadric {
public:
    Hyperboloid(Vec3d p1, Vec3d p2, double ah, double ch, double phiMax, const Transform& toGroup, bool ro)
        : Quadric(toGroup, ro, phiMax), p1_(p1), p2_(p2), ah_(ah), ch_(ch), zMin_(std::min(p1.z, p2.z)),
          zMax_(std::max(p1.z, p2.z)), rMax_(std::max(std::hypot(p1.x, p1.y), std::hypot(p2.x, p2.y))) {
        // Simpson's rule on each bin: the bins' areas (per radian) and their running sums.
        const double dz = (zMax_ - zMin_) / kAreaBins;
        for (int i = 0; i < kAreaBins; ++i) {
            const double z0 = zMin_ + i * dz;
            const double w = dz / 6 * (areaDensity(z0) + 4 * areaDensity(z0 + dz / 2) + areaDensity(z0 + dz));
            cdf_[i + 1] = cdf_[i] + w;
        }
    }

    double objectArea() const override { return phiMax_ * cdf_[kAreaBins]; }
    void uv(Vec3d p, double& u, double& v) const override {
        v = (p.z - p1_.z) / (p2_.z - p1_.z);
        u = relativePhi(p, v) / phiMax_;
    }

    // The radius at height z; the surface exists where this is real.
    double radius2(double z) const { return (1 + ch_ * z * z) / ah_; }

protected:
    bool intersect(Vec3d o, Vec3d d, double tMin, double tMax, double& t) const override {
        return nearestRoot(ah_ * (d.x * d.x + d.y * d.y) - ch_ * d.z * d.z, 2 * (ah_ * (d.x * o.x + d.y * o.y) - ch_ * d.z * o.z),
                           ah_ * (o.x * o.x + o.y * o.y) - ch_ * o.z * o.z - 1, o, d, tMin, tMax, t);
    }
    bool accepts(Vec3d p) const override {
        return p.z >= zMin_ && p.z <= zMax_ && relativePhi(p, (p.z - p1_.z) / (p2_.z - p1_.z)) <= phiMax_;
    }
    // The gradient points away from the axis; dp/du x dp/dv does so only when v grows with z.
    Vec3d normal(Vec3d p) const override {
        const double s = p2_.z > p1_.z ? 1 : -1;
        return {s * ah_ * p.x, s * ah_ * p.y, -s * ch_ * p.z};
    }
    // pbrt-v3's dp/dv: the segment p1-p2 turned by the point's phi (exact when the segment is a
    // ruling of the surface).
    void partials(Vec3d p, Vec3d& dpdu, Vec3d& dpdv) const override {
        const double phi = relativePhi(p, (p.z - p1_.z) / (p2_.z - p1_.z));
        const Vec3d d = p2_ - p1_;
        dpdu = azimuthalPartial(p);
        dpdv = {d.x * std::cos(phi) - d.y * std::sin(phi), d.x * std::sin(phi) + d.y * std::cos(phi), d.z};
    }
    // The rulings are straight (d2p/dv2 = 0); d2p/du dv turns dp/dv about the axis.
    void secondPartials(Vec3d p, Vec3d& duu, Vec3d& duv, Vec3d& dvv) const override {
        Vec3d dpdu, dpdv;
        partials(p, dpdu, dpdv);
        duu = azimuthalSecondPartial(p);
        duv = phiMax_ * Vec3d{-dpdv.y, dpdv.x, 0};
        dvv = {};
    }
    void bounds(Vec3d& lo, Vec3d& hi) const override {
        lo = {-rMax_, -rMax_, zMin_};
        hi = {rMax_, rMax_, zMax_};
    }
    // z from the histogram of area over height (uniform inside a bin), phi uniform.
    Vec3d sample(double u1, double u2) const override {
        const double target = u1 * cdf_[kAreaBins];
        const int i = std::clamp(int(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()) - 1, 0, kAreaBins - 1);
        const double f = cdf_[i + 1] > cdf_[i] ? (target - cdf_[i]) / (cdf_[i + 1] - cdf_[i]) : 0.5;
        const double z = zMin_ + (i + std::clamp(f, 0.0, 1.0)) * (zMax_ - zMin_) / kAreaBins;
        const Vec3d pr = ruling((z - p1_.z) / (p2_.z - p1_.z));
        const double phi = azimuth(pr.x, pr.y) + u2 * phiMax_, rho = std::sqrt(std::max(0.0, radius2(z)));
        return {rho * std::cos(phi), rho * std::sin(phi), z};
    }
    double objectPdf(Vec3d p) const override {
        const double dz = (zMax_ - zMin_) / kAreaBins;
        const int i = std::clamp(int((p.z - zMin_) / dz), 0, kAreaBins - 1);
        const double pz = (cdf_[i + 1] - cdf_[i]) / (cdf_[kAreaBins] * dz);
        return pz / (phiMax_ * areaDensity(p.z));
    }

private:
    Vec3d ruling(double v) const { return (1 - v) * p1_ + v * p2_; }
    double relativePhi(Vec3d p, double v) const {
        const Vec3d pr = ruling(v);
        const double phi = std::atan2(pr.x * p.y - p.x * pr.y, p.x * pr.x + p.y * pr.y);
        return phi < 0 ? phi + 2 * M_PI : phi;
    }
    // Area per unit height and radian: rho sqrt(1 + rho'^2) = sqrt(rho^2 + (rho rho')^2).
    double areaDensity(double z) const {
        const double rr = ch_ * z / ah_;
        return std::sqrt(std::max(0.0, radius2(z) + rr * rr));
    }

    Vec3d p1_, p2_;
    double ah_, ch_, zMin_, zMax_, rMax_;
    std::array<double, kAreaBins + 1> cdf_{};
};

}  // namespace

std::shared_ptr<const Shape> makeHyperboloid(const ParamSet& params, const Transform& toGroup, bool ro) {
    const Vec3f a = params.getPoint("p1", {0, 0, 0}), b = params.getPoint("p2", {1, 1, 1});
    const double phiMax = params.getFloat("phimax", 360);
    if (!(phiMax > 0)) params.fail("phimax must be positive");
    Vec3d p1{a.x, a.y, a.z}, p2{b.x, b.y, b.z};
    if (p1.z == p2.z) params.fail("p1 and p2 must differ in z");
    if (p2.z == 0) std::swap(p1, p2);
    // pbrt-v3's fit, in its single precision: the implicit surface through p2 and a point further
    // along the line, stepping on while the two equations are singular. A line that meets the axis
    // (a cone) never fits.
    float ah = NAN, ch = NAN;
    const float qx = float(p2.x), qy = float(p2.y), qz = float(p2.z);
    float ppx = float(p1.x), ppy = float(p1.y), ppz = float(p1.z);
    for (int step = 0; step < 64 && !std::isfinite(ah); ++step) {
        ppx += 2.0f * (qx - float(p1.x));
        ppy += 2.0f * (qy - float(p1.y));
        ppz += 2.0f * (qz - float(p1.z));
        const float xy1 = ppx * ppx + ppy * ppy, xy2 = qx * qx + qy * qy;
        ah = (1.0f / xy1 - (ppz * ppz) / (xy1 * qz * qz)) / (1 - (xy2 * ppz * ppz) / (xy1 * qz * qz));
        ch = (ah * xy2 - 1) / (qz * qz);
    }
    if (!std::isfinite(ah) || !std::isfinite(ch))
        params.fail("p1 and p2 describe no hyperboloid (the line through them meets the z axis?)");
    auto s = std::make_shared<Hyperboloid>(p1, p2, ah, ch, phiMax, toGroup, ro);
    if (!(s->radius2(p1.z) >= 0 && s->radius2(p2.z) >= 0))
        params.fail("p1 and p2 describe no hyperboloid of one sheet over their z range");
    s->measure();
    return s;
}

}  // namespace lenslab
