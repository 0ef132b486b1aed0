// Cornell's irregularly sampled isotropic BRDFs, looked up as pbrt-v2 does: each measurement is a
// point in the space (sin theta_i sin theta_o, delta phi / pi, cos theta_i cos theta_o), which
// treats the two directions alike (reciprocity) and is smooth across the pole; a query averages
// the nearby measurements with Gaussian weights exp(-100 d^2), widening the search until more than
// two are found.
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "materials/MeasuredBrdf.h"
#include "core/Spectrum.h"

namespace lenslab {

namespace {

constexpr int kGrid = 16;  // cells per axis of the lookup grid over [0, 1]^3

struct Measurement {
    Vec3f point, value;
};

Vec3f remap(float cosI, float sinI, float phiI, float cosO, float sinO, float phiO) {
    float dphi = std::fabs(phiI - phiO);
    dphi = std::fmod(dphi, 2.0f * float(M_PI));
    if (dphi > float(M_PI)) dphi = 2.0f * float(M_PI) - dphi;
    return {sinI * sinO, dphi / float(M_PI), cosI * cosO};
}

int cellOf(float x) { return std::clamp(int(std::floor(x * kGrid)), 0, kGrid - 1); }

class IrregularBrdf final : public MeasuredBrdf {
public:
    explicit IrregularBrdf(std::vector<Measurement> m) : measurements_(std::move(m)) {
        for (std::size_t i = 0; i < measurements_.size(); ++i) {
            const Vec3f p = measurements_[i].point;
            cells_[index(cellOf(p.x), cellOf(p.y), cellOf(p.z))].push_back(i);
        }
    }

    Vec3f f(Vec3f wo, Vec3f wi) const override {
        const auto sinOf = [](Vec3f w) { return std::sqrt(std::max(0.0f, 1.0f - w.z * w.z)); };
        const Vec3f q = remap(wi.z, sinOf(wi), std::atan2(wi.y, wi.x), wo.z, sinOf(wo), std::atan2(wo.y, wo.x));
        for (float r2 = 0.001f;; r2 *= 2.0f) {
            int found = 0;
            float weights = 0;
            Vec3f sum{};
            gather(q, r2, [&](const Measurement& m, float d2) {
                const float w = std::exp(-100.0f * d2);
                sum += w * m.value;
                weights += w;
                ++found;
            });
            if (found > 2 || r2 > 1.5f) return weights > 0 ? sum / weights : Vec3f{};
        }
    }

private:
    static int index(int x, int y, int z) { return (z * kGrid + y) * kGrid + x; }

    template <class Visit>
    void gather(Vec3f q, float r2, Visit&& visit) const {
        const float r = std::sqrt(r2);
        const int x0 = cellOf(q.x - r), x1 = cellOf(q.x + r), y0 = cellOf(q.y - r), y1 = cellOf(q.y + r);
        const int z0 = cellOf(q.z - r), z1 = cellOf(q.z + r);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    for (std::size_t i : cells_[index(x, y, z)]) {
                        const Vec3f d = measurements_[i].point - q;
                        const float d2 = dot(d, d);
                        if (d2 <= r2) visit(measurements_[i], d2);
                    }
    }

    std::vector<Measurement> measurements_;
    std::array<std::vector<std::size_t>, kGrid * kGrid * kGrid> cells_;
};

// Every number in the file, '#' comments skipped; anything else is an error naming its line.
std::vector<double> readNumbers(const std::string& path, const std::string& name, const ParamSet& params) {
    std::ifstream in(path);
    if (!in) params.fail("cannot open measured BRDF '" + name + "'");
    std::vector<double> numbers;
    std::string line, word;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        std::istringstream words(line.substr(0, line.find('#')));
        while (words >> word) {
            char* end = nullptr;
            const double v = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0' || !std::isfinite(v))
                params.fail("measured BRDF '" + name + "' line " + std::to_string(lineNo) + ": '" + word +
                            "' is not a number");
            numbers.push_back(v);
        }
    }
    return numbers;
}

}  // namespace

std::shared_ptr<const MeasuredBrdf> loadIrregularBrdf(const std::string& path, const std::string& name,
                                                      const ParamSet& params) {
    const std::vector<double> v = readNumbers(path, name, params);
    const auto bad = [&](const std::string& why) { params.fail("measured BRDF '" + name + "': " + why); };
    if (v.empty() || v[0] < 1 || v[0] != std::floor(v[0]) || v[0] > 10000) bad("must start with the number of wavelengths");
    const std::size_t nWl = std::size_t(v[0]);
    if (v.size() < 1 + nWl) bad("fewer wavelengths than announced");
    const std::vector<double> lambda(v.begin() + 1, v.begin() + 1 + std::ptrdiff_t(nWl));
    for (std::size_t i = 1; i < nWl; ++i)
        if (!(lambda[i] > lambda[i - 1])) bad("wavelengths must increase");
    const std::size_t recordSize = 4 + nWl, rest = v.size() - 1 - nWl;
    if (rest == 0 || rest % recordSize != 0)
        bad(std::to_string(rest) + " numbers after the wavelengths: not a whole number of records of " +
            std::to_string(recordSize) + " (theta_i phi_i theta_o phi_o and one value per wavelength)");
    std::vector<Measurement> measurements;
    for (std::size_t at = 1 + nWl; at < v.size(); at += recordSize) {
        const float thetaI = float(v[at]), phiI = float(v[at + 1]), thetaO = float(v[at + 2]), phiO = float(v[at + 3]);
        const std::vector<double> values(v.begin() + std::ptrdiff_t(at + 4), v.begin() + std::ptrdiff_t(at + recordSize));
        const Vec3f point = remap(std::cos(thetaI), std::sin(thetaI), phiI, std::cos(thetaO), std::sin(thetaO), phiO);
        const Vec3f rgb = sampledSpectrumToRgb(lambda, values);
        measurements.push_back({point, {std::max(0.0f, rgb.x), std::max(0.0f, rgb.y), std::max(0.0f, rgb.z)}});
    }
    return std::make_shared<IrregularBrdf>(std::move(measurements));
}

}  // namespace lenslab
