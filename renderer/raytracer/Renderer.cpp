// renderScene: scene -> camera + Embree geometry -> tiles rendered in parallel (TBB) -> image.
// Every sample depends only on (seed, pixel, sample index), so the image is the same for any
// thread count and any tile order.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <xmmintrin.h>
#include <pmmintrin.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <sstream>
#include <thread>

#include "CameraFactory.h"
#include "PathIntegrator.h"
#include "PixelFilter.h"
#include "Render.h"
#include "SceneGeometry.h"
#include "TileScheduler.h"

namespace lenslab {

namespace {

constexpr int kMaxSide = 16384;
constexpr long long kMaxPixels = 64LL * 1024 * 1024;
constexpr int kMaxSpp = 1 << 20;

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Counters {
    std::atomic<std::uint64_t> cameraRays{0}, blocked{0}, traced{0};
};

struct FrameSetup {
    int width = 0, height = 0, spp = 0;
    PixelRect area;  // rendered pixels, in full-image coordinates
};

FrameSetup frameSetup(const SceneDescription& scene, const RenderSettings& s) {
    FrameSetup f;
    f.width = s.width.value_or(scene.film.xresolution);
    f.height = s.height.value_or(scene.film.yresolution);
    const std::string from = s.width || s.height ? "the render settings" : describe(scene.film.where);
    if (f.width < 1 || f.height < 1 || f.width > kMaxSide || f.height > kMaxSide ||
        (long long)f.width * f.height > kMaxPixels)
        throw SceneError(from + ": resolution " + std::to_string(f.width) + "x" + std::to_string(f.height) +
                         " is out of range (each side 1 to 16384 pixels, at most 64 Mpixels)");
    f.spp = s.spp.value_or(scene.pixelSamples);
    if (f.spp < 1 || f.spp > kMaxSpp)
        throw SceneError("samples per pixel " + std::to_string(f.spp) + " out of range (1 to 1048576)");
    const std::array<double, 4> c = s.crop.value_or(scene.film.crop);
    if (!(c[0] >= 0 && c[0] < c[1] && c[1] <= 1 && c[2] >= 0 && c[2] < c[3] && c[3] <= 1))
        throw SceneError("crop window x0,x1,y0,y1 must satisfy 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1");
    // pbrt-v3's rounding of the crop window to pixels.
    f.area = {int(std::ceil(f.width * c[0])), int(std::ceil(f.height * c[2])), int(std::ceil(f.width * c[1])),
              int(std::ceil(f.height * c[3]))};
    if (f.area.x1 <= f.area.x0 || f.area.y1 <= f.area.y0) throw SceneError("the crop window holds no pixel");
    return f;
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += (s.empty() ? "" : "\n") + l;
    return s;
}

}  // namespace

RenderOutput renderScene(const RenderSettings& settings, const std::function<void(const TileUpdate&, const Image&)>& onTile,
                         const std::atomic<bool>* cancel) {
    const auto start = Clock::now();
    if (settings.tileSize < 1 || settings.tileSize > 4096) throw SceneError("tile size must lie in [1, 4096] pixels");
    if (settings.threads < 0 || settings.threads > 1024) throw SceneError("thread count must lie in [0, 1024]");
    SceneDescription scene = parseSceneFile(settings.scenePath);
    const FrameSetup frame = frameSetup(scene, settings);
    const int threads = settings.threads > 0 ? settings.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    tbb::task_arena arena(threads);

    const PixelFilter filter(scene.filter);
    std::unique_ptr<Camera> camera;
    std::unique_ptr<SceneGeometry> geometry;
    arena.execute([&] {
        camera = makeCamera(scene, settings.camera, frame.width, frame.height, filter.radius());
        geometry = std::make_unique<SceneGeometry>(scene);
    });
    const PathIntegrator integrator(*geometry, scene.integrator);

    RenderOutput out;
    out.stats.setupSeconds = secondsSince(start);
    Image& image = out.image;
    image.width = frame.area.x1 - frame.area.x0;
    image.height = frame.area.y1 - frame.area.y0;
    image.rgb.assign(std::size_t(image.width) * image.height * 3, 0.0f);

    const std::vector<PixelRect> tiles = makeTiles(frame.area, settings.tileSize);
    Counters counters;
    std::mutex tileMutex;
    int tilesDone = 0;
    const auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
    const auto renderStart = Clock::now();

    const auto renderTile = [&](const PixelRect& tile) {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        std::uint64_t cameraRays = 0, blocked = 0, traced = 0;
        std::vector<CameraSample> samples(frame.spp);
        std::vector<CameraRay> rays(frame.spp);
        for (int py = tile.y0; py < tile.y1; ++py) {
            if (cancelled()) return;
            for (int px = tile.x0; px < tile.x1; ++px) {
                const std::uint64_t pixelSeed = hashCombine(settings.seed, (std::uint64_t(py) << 32) | std::uint32_t(px));
                std::uint32_t scramble[4];
                for (int k = 0; k < 4; ++k) scramble[k] = std::uint32_t(mix64(pixelSeed + k));
                for (int s = 0; s < frame.spp; ++s) {
                    float dx, dy;
                    filter.sample(sobolSample(s, 0, scramble[0]), sobolSample(s, 1, scramble[1]), dx, dy);
                    samples[s] = {px + 0.5 + dx, py + 0.5 + dy, sobolSample(s, 2, scramble[2]), sobolSample(s, 3, scramble[3])};
                }
                camera->generateRays(samples.data(), samples.size(), rays.data());
                Vec3f sum{};
                for (int s = 0; s < frame.spp; ++s) {
                    const CameraRay& ray = rays[s];
                    if (!(ray.weight > 0)) {
                        ++blocked;
                        continue;
                    }
                    Pcg32 rng(hashCombine(pixelSeed, std::uint64_t(s)));
                    sum += ray.weight * integrator.radiance(ray.origin, ray.direction, rng, traced);
                }
                cameraRays += frame.spp;
                float* dst = &image.rgb[(std::size_t(py - frame.area.y0) * image.width + (px - frame.area.x0)) * 3];
                dst[0] = sum.x / frame.spp;
                dst[1] = sum.y / frame.spp;
                dst[2] = sum.z / frame.spp;
            }
        }
        counters.cameraRays += cameraRays;
        counters.blocked += blocked;
        counters.traced += traced;
        std::lock_guard<std::mutex> lock(tileMutex);
        ++tilesDone;
        if (onTile && !cancelled()) {
            TileUpdate u{tile.x0 - frame.area.x0, tile.y0 - frame.area.y0, tile.x1 - frame.area.x0,
                         tile.y1 - frame.area.y0, tilesDone, int(tiles.size())};
            onTile(u, image);
        }
    };
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
                if (!cancelled()) renderTile(tiles[i]);
        });
    });
    if (cancelled()) throw RenderCancelled();

    out.stats.renderSeconds = secondsSince(renderStart);
    out.stats.cameraRays = counters.cameraRays;
    out.stats.blockedCameraRays = counters.blocked;
    out.stats.raysTraced = counters.traced;
    out.metadata = camera->describe();
    std::ostringstream crop;
    crop << frame.area.x0 << "," << frame.area.x1 << "," << frame.area.y0 << "," << frame.area.y1;
    out.metadata["scene"] = scene.file;
    out.metadata["resolution"] = std::to_string(frame.width) + "x" + std::to_string(frame.height);
    out.metadata["cropPixels"] = crop.str();
    out.metadata["spp"] = std::to_string(frame.spp);
    out.metadata["seed"] = std::to_string(settings.seed);
    out.metadata["integrator"] = std::string(scene.integrator.directOnly ? "directlighting" : "path") +
                                 " maxdepth " + std::to_string(scene.integrator.maxDepth);
    out.metadata["units"] = "world metres, lens millimetres";
    if (!scene.film.filename.empty()) out.metadata["filmFilename"] = scene.film.filename;
    if (!scene.warnings.empty()) out.metadata["warnings"] = joinLines(scene.warnings);
    return out;
}

}  // namespace lenslab
