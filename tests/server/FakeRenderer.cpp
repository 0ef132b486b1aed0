#include "FakeRenderer.h"

#include <algorithm>
#include <chrono>
#include <thread>

namespace lenslab {

namespace {

const int kTile = 16;

}  // namespace

RenderedImages FakeRenderer::render(const RenderJobInput& job, const TileCallback& onTile,
                                    const std::atomic<bool>& cancel) {
    struct Running {
        std::atomic<int>& count;
        ~Running() { --count; }
    } running{running_};
    const int now = ++running_;
    int seen = mostAtOnce_;
    while (now > seen && !mostAtOnce_.compare_exchange_weak(seen, now)) {}

    RenderOutput output;
    Image& image = output.image;
    image.width = job.request.width;
    image.height = job.request.height;
    image.rgb.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0.0f);
    const int tilesX = (image.width + kTile - 1) / kTile, tilesY = (image.height + kTile - 1) / kTile;
    int done = 0;
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx) {
            if (cancel) throw RenderCancelled();
            std::this_thread::sleep_for(std::chrono::milliseconds(job.request.spp));
            const int x0 = tx * kTile, y0 = ty * kTile;
            const int x1 = std::min(x0 + kTile, image.width), y1 = std::min(y0 + kTile, image.height);
            for (int y = y0; y < y1; ++y)
                std::fill(image.rgb.begin() + (static_cast<std::size_t>(y) * image.width + x0) * 3,
                          image.rgb.begin() + (static_cast<std::size_t>(y) * image.width + x1) * 3, 0.18f);
            if (onTile) onTile({x0, y0, x1, y1, ++done, tilesX * tilesY}, image);
        }
    ++rendered_;
    RenderedImages images;
    images.png = encodePng(image);
    images.exr = encodeExr(output);
    images.stats = {{"fake", true}};
    return images;
}

std::vector<std::uint8_t> FakeRenderer::encodePreview(const Image& partial) const { return encodePng(partial); }

}  // namespace lenslab
