#pragma once
// The JobRenderer the service uses: lenslab's ray tracer with the request's camera settings, the
// result encoded as PNG (sRGB) and EXR (linear, with the camera and lens in its header).
#include "jobs/JobRenderer.h"

namespace lenslab {

class EngineRenderer : public JobRenderer {
public:
    explicit EngineRenderer(int threads) : threads_(threads) {}
    RenderedImages render(const RenderJobInput& job, const TileCallback& onTile, const std::atomic<bool>& cancel) override;
    std::vector<std::uint8_t> encodePreview(const Image& partial) const override;

private:
    int threads_;
};

}  // namespace lenslab
