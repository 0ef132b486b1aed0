#include "EngineRenderer.h"

namespace lenslab {

RenderedImages EngineRenderer::render(const RenderJobInput& job, const TileCallback& onTile,
                                      const std::atomic<bool>& cancel) {
    RenderSettings settings;
    settings.scenePath = job.scenePath;
    settings.confined = true;
    settings.camera.lensFile = job.lensPath;
    settings.camera.lensLayout = job.lensLayout;
    const LensSettings lens = lensSettings(job.request);
    settings.camera.fstop = lens.fstop;
    settings.camera.focusDistance = lens.focusDistance;
    settings.camera.filmDiagonal = job.request.filmDiagonal;
    settings.camera.mode = job.request.mode;
    settings.camera.spectral = job.request.spectral;
    settings.spp = job.request.spp;
    settings.width = job.request.width;
    settings.height = job.request.height;
    settings.threads = threads_;
    const RenderOutput output = renderScene(settings, onTile, &cancel);
    RenderedImages images;
    images.png = encodePng(output.image);
    images.exr = encodeExr(output);
    images.stats = {{"setup_s", output.stats.setupSeconds},
                    {"render_s", output.stats.renderSeconds},
                    {"camera_rays", output.stats.cameraRays},
                    {"blocked_camera_rays", output.stats.blockedCameraRays},
                    {"rays_traced", output.stats.raysTraced}};
    return images;
}

std::vector<std::uint8_t> EngineRenderer::encodePreview(const Image& partial) const { return encodePng(partial); }

}  // namespace lenslab
