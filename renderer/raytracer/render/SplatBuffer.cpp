#include "render/SplatBuffer.h"

#include <algorithm>
#include <stdexcept>

namespace lenslab {

namespace {

// A margin the box grows by beyond what is asked, so that a row's splats rarely reallocate.
constexpr int kGrowth = 4;

}  // namespace

void SplatBuffer::reach(const PixelRect& r) {
    if (!rgb_.empty() && r.x0 >= box_.x0 && r.x1 <= box_.x1 && r.y0 >= box_.y0 && r.y1 <= box_.y1) return;
    const PixelRect grown = rgb_.empty() ? PixelRect{r.x0 - kGrowth, r.y0 - kGrowth, r.x1 + kGrowth, r.y1 + kGrowth}
                                         : PixelRect{std::min(box_.x0, r.x0 - kGrowth), std::min(box_.y0, r.y0 - kGrowth),
                                                     std::max(box_.x1, r.x1 + kGrowth), std::max(box_.y1, r.y1 + kGrowth)};
    std::vector<float> rgb(std::size_t(grown.x1 - grown.x0) * std::size_t(grown.y1 - grown.y0) * 3, 0.0f);
    const std::size_t oldWidth = std::size_t(box_.x1 - box_.x0), newWidth = std::size_t(grown.x1 - grown.x0);
    for (int y = box_.y0; y < box_.y1 && !rgb_.empty(); ++y)
        std::copy_n(&rgb_[std::size_t(y - box_.y0) * oldWidth * 3], oldWidth * 3,
                    &rgb[(std::size_t(y - grown.y0) * newWidth + std::size_t(box_.x0 - grown.x0)) * 3]);
    box_ = grown;
    rgb_ = std::move(rgb);
}

void SplatBuffer::add(int x, int y, Vec3f value) {
    if (rgb_.empty() || x < box_.x0 || x >= box_.x1 || y < box_.y0 || y >= box_.y1) reach({x, y, x + 1, y + 1});
    float* p = &rgb_[(std::size_t(y - box_.y0) * std::size_t(box_.x1 - box_.x0) + std::size_t(x - box_.x0)) * 3];
    p[0] += value.x;
    p[1] += value.y;
    p[2] += value.z;
}

void SplatBuffer::add(const SplatBuffer& other) {
    if (other.empty()) return;
    reach(other.box_);
    const std::size_t width = std::size_t(box_.x1 - box_.x0), otherWidth = std::size_t(other.box_.x1 - other.box_.x0);
    for (int y = other.box_.y0; y < other.box_.y1; ++y) {
        const float* from = &other.rgb_[std::size_t(y - other.box_.y0) * otherWidth * 3];
        float* to = &rgb_[(std::size_t(y - box_.y0) * width + std::size_t(other.box_.x0 - box_.x0)) * 3];
        for (std::size_t i = 0; i < otherWidth * 3; ++i) to[i] += from[i];
    }
}

void SplatBuffer::clear() {
    box_ = {};
    rgb_.clear();
}

SplatBuffer SplatBuffer::fromParts(const PixelRect& box, std::vector<float> rgb) {
    if (rgb.size() != std::size_t(std::max(box.x1 - box.x0, 0)) * std::size_t(std::max(box.y1 - box.y0, 0)) * 3)
        throw std::runtime_error("a splat buffer whose pixels do not fill its box");
    SplatBuffer b;
    if (rgb.empty()) return b;
    b.box_ = box;
    b.rgb_ = std::move(rgb);
    return b;
}

}  // namespace lenslab
