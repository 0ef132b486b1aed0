#include "render/SplatImage.h"

#include <stdexcept>

namespace lenslab {

SplatImage::SplatImage(std::size_t tiles) : waiting_(tiles), done_(tiles, false) {}

void SplatImage::tileDone(std::size_t tile, SplatBuffer splats) {
    if (tile >= done_.size() || done_[tile]) return;
    done_[tile] = true;
    waiting_[tile] = std::move(splats);
    for (; next_ < done_.size() && done_[next_]; ++next_) {
        sum_.add(waiting_[next_]);
        waiting_[next_] = {};
    }
}

const SplatBuffer& SplatImage::sum() const {
    if (next_ != done_.size()) throw std::logic_error("a frame's splats summed before every tile was done");
    return sum_;
}

}  // namespace lenslab
