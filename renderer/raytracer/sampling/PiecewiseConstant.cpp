#include "sampling/PiecewiseConstant.h"

#include <algorithm>

namespace lenslab {

namespace {

std::vector<float> rowIntegrals(const std::vector<PiecewiseConstant1D>& rows) {
    std::vector<float> v;
    v.reserve(rows.size());
    for (const auto& r : rows) v.push_back(r.integral());
    return v;
}

std::vector<PiecewiseConstant1D> makeRows(const std::vector<float>& values, int width, int height) {
    std::vector<PiecewiseConstant1D> rows;
    rows.reserve(std::size_t(height));
    for (int y = 0; y < height; ++y)
        rows.emplace_back(std::vector<float>(values.begin() + std::ptrdiff_t(y) * width,
                                             values.begin() + std::ptrdiff_t(y + 1) * width));
    return rows;
}

}  // namespace

PiecewiseConstant1D::PiecewiseConstant1D(std::vector<float> f) : f_(std::move(f)) {
    if (f_.empty()) f_.assign(1, 0.0f);
    for (float& v : f_) v = v > 0 ? v : 0.0f;  // also NaN
    const std::size_t n = f_.size();
    cdf_.assign(n + 1, 0.0f);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sum += f_[i];
        cdf_[i + 1] = float(sum);
    }
    integral_ = float(sum / double(n));
    if (!(sum > 0)) {  // nothing to prefer: uniform
        for (std::size_t i = 0; i <= n; ++i) cdf_[i] = float(i) / float(n);
        return;
    }
    for (std::size_t i = 1; i <= n; ++i) cdf_[i] = float(cdf_[i] / sum);
    cdf_[n] = 1.0f;
}

std::size_t PiecewiseConstant1D::findBin(float u) const {
    // The last bin whose cdf start lies at or below u, skipping empty bins.
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    return std::size_t(std::clamp<std::ptrdiff_t>(it - cdf_.begin() - 1, 0, std::ptrdiff_t(f_.size()) - 1));
}

float PiecewiseConstant1D::binProbability(std::size_t bin) const { return cdf_[bin + 1] - cdf_[bin]; }

float PiecewiseConstant1D::sampleContinuous(float u, float& pdf, std::size_t& bin) const {
    bin = findBin(u);
    const float p = binProbability(bin);
    const float within = p > 0 ? (u - cdf_[bin]) / p : 0.5f;
    pdf = p * float(f_.size());
    return std::min((float(bin) + std::clamp(within, 0.0f, 1.0f)) / float(f_.size()), 0x1.fffffep-1f);
}

std::size_t PiecewiseConstant1D::sampleDiscrete(float u, float& pmf) const {
    const std::size_t bin = findBin(u);
    pmf = binProbability(bin);
    return bin;
}

float PiecewiseConstant1D::density(float x) const {
    const std::size_t bin = std::size_t(std::clamp(int(x * float(f_.size())), 0, int(f_.size()) - 1));
    return binProbability(bin) * float(f_.size());
}

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<float>& values, int width, int height)
    : rows_(makeRows(values, width, height)), marginal_(rowIntegrals(rows_)) {}

void PiecewiseConstant2D::sample(float u1, float u2, float& s, float& t, float& pdf) const {
    float pdfT, pdfS;
    std::size_t row;
    t = marginal_.sampleContinuous(u2, pdfT, row);
    std::size_t column;
    s = rows_[row].sampleContinuous(u1, pdfS, column);
    pdf = pdfT * pdfS;
}

float PiecewiseConstant2D::density(float s, float t) const {
    const std::size_t row = std::size_t(std::clamp(int(t * float(rows_.size())), 0, int(rows_.size()) - 1));
    return marginal_.density(t) * rows_[row].density(s);
}

}  // namespace lenslab
