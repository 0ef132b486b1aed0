// renderScene: a PreparedFrame whose tiles are rendered in parallel (TBB) into one image.
// Every sample depends only on (seed, pixel, sample index), so the image is the same for any
// thread count and any tile order.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <mutex>

#include "render/PreparedFrame.h"
#include "render/RenderWarnings.h"
#include "render/SplatImage.h"
#include "Render.h"

namespace lenslab {

RenderOutput renderScene(const RenderSettings& settings, const std::function<void(const TileUpdate&, const Image&)>& onTile,
                         const std::atomic<bool>* cancel) {
    PreparedFrame frame(settings, cancel);
    RenderOutput out;
    out.stats.setupSeconds = frame.setupSeconds();
    Image& image = out.image;
    image.width = frame.imageWidth();
    image.height = frame.imageHeight();
    image.rgb.assign(std::size_t(image.width) * image.height * 3, 0.0f);

    const std::vector<PixelRect>& tiles = frame.tiles();
    const PixelRect& area = frame.area();
    SplatImage splats(tiles.size());
    std::mutex tileMutex;
    TileCounters counters;
    int tilesDone = 0;
    const auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
    const auto renderStart = std::chrono::steady_clock::now();

    const auto renderTile = [&](std::size_t index) {
        const PixelRect& tile = tiles[index];
        TileCounters tileCounters;
        SplatBuffer tileSplats;
        float* dst = &image.rgb[(std::size_t(tile.y0 - area.y0) * image.width + (tile.x0 - area.x0)) * 3];
        const bool complete = frame.renderRect(tile, dst, std::size_t(image.width) * 3, tileCounters, tileSplats, cancel);
        std::lock_guard<std::mutex> lock(tileMutex);
        counters += tileCounters;
        if (!complete) return;
        splats.tileDone(index, std::move(tileSplats));
        ++tilesDone;
        if (onTile && !cancelled()) {
            const TileUpdate u{tile.x0 - area.x0, tile.y0 - area.y0, tile.x1 - area.x0, tile.y1 - area.y0, tilesDone,
                               int(tiles.size())};
            onTile(u, image);
        }
    };
    frame.arena().execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
                if (!cancelled()) renderTile(i);
        });
    });
    if (cancelled()) throw RenderCancelled();
    out.metadata = frame.metadata();
    out.raw = frame.finishImage(splats.sum(), image, out.metadata);

    out.stats.renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count();
    out.stats.cameraRays = counters.cameraRays;
    out.stats.blockedCameraRays = counters.blockedCameraRays;
    out.stats.raysTraced = counters.raysTraced;
    out.stats.flareSources = frame.flareStats().sources;
    out.stats.flarePaths = frame.flareStats().paths;
    out.stats.flareRays = frame.flareStats().raysTraced;
    out.stats.flareSeconds = frame.flareStats().seconds;
    addRenderWarnings(out, frame);
    return out;
}

}  // namespace lenslab
