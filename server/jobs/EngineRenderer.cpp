#include "jobs/EngineRenderer.h"

#include "jobs/RenderJobResolver.h"

namespace lenslab {

RenderedImages EngineRenderer::render(const RenderJobInput& job, const TileCallback& onTile,
                                      const std::atomic<bool>& cancel) {
    RenderSettings settings = renderSettings(job);
    settings.threads = threads_;
    const RenderOutput output = renderScene(settings, onTile, &cancel);
    RenderedImages images;
    images.png = encodePng(output.image);
    images.exr = encodeExr(output);
    images.stats = {{"setup_s", output.stats.setupSeconds},
                    {"render_s", output.stats.renderSeconds},
                    {"camera_rays", output.stats.cameraRays},
                    {"blocked_camera_rays", output.stats.blockedCameraRays},
                    {"rays_traced", output.stats.raysTraced},
                    {"flare_paths", output.stats.flarePaths},
                    {"flare_rays", output.stats.flareRays},
                    {"flare_s", output.stats.flareSeconds}};
    images.warnings = output.warnings;
    return images;
}

std::vector<std::uint8_t> EngineRenderer::encodePreview(const Image& partial) const { return encodePng(partial); }

}  // namespace lenslab
