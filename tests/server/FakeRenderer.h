#pragma once
// A stand-in for the ray tracer: 16-pixel tiles, each taking `spp` milliseconds, a flat grey image.
// Lets tests drive the queue (limits, cancellation, restarts, crashes) quickly and predictably.
#include <atomic>

#include "jobs/JobRenderer.h"

namespace lenslab {

class FakeRenderer : public JobRenderer {
public:
    RenderedImages render(const RenderJobInput& job, const TileCallback& onTile, const std::atomic<bool>& cancel) override;
    std::vector<std::uint8_t> encodePreview(const Image& partial) const override;

    int mostAtOnce() const { return mostAtOnce_; }
    int rendered() const { return rendered_; }

private:
    std::atomic<int> running_{0}, mostAtOnce_{0}, rendered_{0};
};

}  // namespace lenslab
