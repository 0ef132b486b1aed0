#pragma once
// One frame ready to render: the scene parsed, the camera (pupil bounds, focus) and the Embree
// scene built, the tiles listed. Any process holding the same settings builds the same frame, and
// a pixel's value depends only on (seed, pixel, sample), so tiles rendered by different threads,
// processes or machines combine into exactly the image of a single-process render.
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cameras/Camera.h"
#include "cameras/Shutter.h"
#include "integrators/Integrator.h"
#include "film/FilmColour.h"
#include "film/PixelFilter.h"
#include "film/SensorReadout.h"
#include "film/SpectralSensor.h"
#include "Render.h"
#include "scene/SceneDescription.h"
#include "geometry/SceneGeometry.h"
#include "render/FlareLayer.h"
#include "render/HeroWavelengths.h"
#include "render/SplatBuffer.h"
#include "render/TileScheduler.h"

namespace lenslab {

// What a tile's rendering counted, summed into RenderStats.
struct TileCounters {
    std::uint64_t cameraRays = 0, blockedCameraRays = 0, raysTraced = 0;
    TileCounters& operator+=(const TileCounters& o) {
        cameraRays += o.cameraRays;
        blockedCameraRays += o.blockedCameraRays;
        raysTraced += o.raysTraced;
        return *this;
    }
};

class PreparedFrame {
public:
    // Throws SceneError, OpticsError. Uses settings.threads threads (0 = all cores) here and in
    // arena(); the camera setup runs inside it.
    // A set *cancel stops the camera's setup too (RenderCancelled).
    explicit PreparedFrame(const RenderSettings& settings, const std::atomic<bool>* cancel = nullptr);
    PreparedFrame(const PreparedFrame&) = delete;
    PreparedFrame& operator=(const PreparedFrame&) = delete;

    // Tiles in full-image pixel coordinates, row-major.
    const std::vector<PixelRect>& tiles() const { return tiles_; }
    // The rendered (cropped) area in full-image pixels; the output image is its size.
    const PixelRect& area() const { return area_; }
    int imageWidth() const { return area_.x1 - area_.x0; }
    int imageHeight() const { return area_.y1 - area_.y0; }
    tbb::task_arena& arena() { return arena_; }
    double setupSeconds() const { return setupSeconds_; }

    // Renders the pixels of `rect` (full-image coordinates) into dst: RGB floats, dst[0] is the
    // pixel (rect.x0, rect.y0), rows rowStride floats apart. Safe to call from many threads for
    // disjoint rects. A spectral frame's samples also leave splats in other pixels, added to
    // `splats` row by row (before the film's scale and white balance; SplatImage adds them up and
    // applies those). Stops early (leaving later rows unwritten, returning false) once *cancel
    // turns true.
    bool renderRect(const PixelRect& rect, float* dst, std::size_t rowStride, TileCounters& counters,
                    SplatBuffer& splats, const std::atomic<bool>* cancel = nullptr) const;

    // The last step on the whole image: the frame's splats (every tile's, SplatImage) added through
    // the film's exposure scale and white balance as renderRect's pixels, then the sensor read out
    // when the settings name one (film/SensorReadout.h), its calibration added to metadata. Returns
    // the sensor's raw numbers when it has a colour mosaic.
    std::optional<RawMosaic> finishImage(const SplatBuffer& splats, Image& image,
                                         std::map<std::string, std::string>& metadata) const;

    bool spectral() const { return spectral_; }
    const FlareStats& flareStats() const { return flare_.stats; }
    // Camera and lens parameters, scene, resolution, spp, seed: the image's metadata.
    std::map<std::string, std::string> metadata() const;
    // What the camera knows its picture will not show (render/RenderWarnings.h).
    std::vector<std::string> cameraWarnings() const { return camera_->warnings(); }

private:
    void addSplats(const SplatBuffer& splats, Image& image) const;

    std::chrono::steady_clock::time_point start_;  // setupSeconds counts from here, the scene parse included
    RenderSettings settings_;
    SceneDescription scene_;
    int width_ = 0, height_ = 0, spp_ = 0;
    PixelRect area_;
    std::vector<PixelRect> tiles_;
    mutable tbb::task_arena arena_;  // the settings' threads; the const finishing step runs in it too
    PixelFilter filter_;
    FilmColour filmColour_;
    Shutter shutter_;
    std::unique_ptr<Camera> camera_;
    std::unique_ptr<SceneGeometry> geometry_;
    std::unique_ptr<Integrator> integrator_;
    bool spectral_ = false;          // wavelengths per sample, the film through SpectralSensor
    int wavelengths_ = 0;            // spectral: per sample (RenderSettings::wavelengthsPerSample)
    SpectralSensor sensor_;
    FlareLayer flare_;               // lens flare, added to every pixel; empty: none
    std::optional<FilmRadiometry> radiometry_;  // the camera's, for a sensor (settings.sensor)
    double setupSeconds_ = 0;
};

}  // namespace lenslab
