// MERL BRDF database tables (Matusik, Pfister, Brand & McMillan, "A Data-Driven Reflectance
// Model", SIGGRAPH 2003), looked up at the nearest table entry in Rusinkiewicz's half/difference
// angles, as pbrt-v2 and MERL's own reader do.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <vector>

#include "materials/MeasuredBrdf.h"

namespace lenslab {

namespace {

constexpr int kThetaH = 90, kThetaD = 90, kPhiD = 180;
constexpr std::size_t kEntries = std::size_t(kThetaH) * kThetaD * kPhiD;
constexpr float kHalfPi = 0.5f * float(M_PI);

// The database stores red, green and blue with these scales (MERL's reader divides them out).
constexpr double kChannelScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

int bin(float x, int count) { return std::clamp(int(x * float(count)), 0, count - 1); }

class MerlBrdf final : public MeasuredBrdf {
public:
    explicit MerlBrdf(std::vector<Vec3f> table) : table_(std::move(table)) {}

    Vec3f f(Vec3f wo, Vec3f wi) const override {
        Vec3f h = wo + wi;
        if (h.z < 0) {  // both below: mirror the pair to the upper side (the table is isotropic)
            h = -h;
            wi = -wi;
        }
        if (h.x == 0 && h.y == 0 && h.z == 0) return {};
        h = normalize(h);
        const float thetaH = std::acos(std::clamp(h.z, -1.0f, 1.0f));
        const float phiH = std::atan2(h.y, h.x);
        // wi in the frame where the half vector is the pole: rotate by -phi_h about z, then by
        // -theta_h about y.
        const float cp = std::cos(phiH), sp = std::sin(phiH), ct = std::cos(thetaH), st = std::sin(thetaH);
        const Vec3f d{dot(wi, Vec3f{cp * ct, sp * ct, -st}), dot(wi, Vec3f{-sp, cp, 0}), dot(wi, h)};
        const float thetaD = std::acos(std::clamp(d.z, -1.0f, 1.0f));
        float phiD = std::atan2(d.y, d.x);
        if (phiD < 0) phiD += float(M_PI);  // reciprocity: phi_d and phi_d + pi hold the same value
        const int iH = bin(std::sqrt(std::max(0.0f, thetaH / kHalfPi)), kThetaH);
        const int iD = bin(thetaD / kHalfPi, kThetaD);
        const int iP = bin(phiD / float(M_PI), kPhiD);
        return table_[(std::size_t(iH) * kThetaD + iD) * kPhiD + iP];
    }

private:
    std::vector<Vec3f> table_;
};

}  // namespace

std::shared_ptr<const MeasuredBrdf> loadMerlBrdf(const std::string& path, const std::string& name,
                                                 const ParamSet& params) {
    std::ifstream in(path, std::ios::binary);
    if (!in) params.fail("cannot open measured BRDF '" + name + "'");
    std::int32_t dims[3] = {0, 0, 0};
    in.read(reinterpret_cast<char*>(dims), sizeof dims);
    if (!in || dims[0] != kThetaH || dims[1] != kThetaD || dims[2] != kPhiD)
        params.fail("measured BRDF '" + name + "' is neither a .brdf text file nor a MERL binary (which starts with "
                    "the table size 90 90 180)");
    std::vector<double> channel(kEntries);
    std::vector<Vec3f> table(kEntries);
    for (int c = 0; c < 3; ++c) {
        in.read(reinterpret_cast<char*>(channel.data()), std::streamsize(kEntries * sizeof(double)));
        if (!in) params.fail("measured BRDF '" + name + "' ends early (a MERL table holds 3 x 90 x 90 x 180 doubles)");
        for (std::size_t i = 0; i < kEntries; ++i) {
            // Negative entries mark directions the measurement did not reach.
            const float v = std::isfinite(channel[i]) ? float(std::max(0.0, channel[i] * kChannelScale[c])) : 0.0f;
            (c == 0 ? table[i].x : c == 1 ? table[i].y : table[i].z) = v;
        }
    }
    return std::make_shared<MerlBrdf>(std::move(table));
}

}  // namespace lenslab
