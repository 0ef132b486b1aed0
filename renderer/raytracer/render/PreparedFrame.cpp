// Scene -> camera + Embree geometry -> tiles, and the per-rect render loop every caller shares
// (local threads in renderScene, MPI workers in renderer/distributed).
#include "render/PreparedFrame.h"

#include <xmmintrin.h>
#include <pmmintrin.h>

#include <cmath>
#include <sstream>
#include <thread>

#include "cameras/CameraFactory.h"
#include "cameras/Shutter.h"
#include "render/HeroWavelengths.h"

namespace lenslab {

namespace {

constexpr int kMaxSide = 16384;
constexpr long long kMaxPixels = 64LL * 1024 * 1024;
constexpr int kMaxSpp = 1 << 20;
constexpr int kCameraBatchRays = 256;  // camera rays made together (a run of pixels' samples)

const RenderSettings& checked(const RenderSettings& s) {
    if (s.tileSize < 1 || s.tileSize > 4096) throw SceneError("tile size must lie in [1, 4096] pixels");
    if (s.threads < 0 || s.threads > 1024) throw SceneError("thread count must lie in [0, 1024]");
    if (s.wavelengthsPerSample < 0 || s.wavelengthsPerSample > kMaxWavelengthsPerSample)
        throw SceneError("wavelengths per sample must lie in [1, " + std::to_string(kMaxWavelengthsPerSample) +
                         "] (0: the film's choice)");
    return s;
}

int threadCount(const RenderSettings& s) {
    return s.threads > 0 ? s.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

// pbrt-v3's Film "maxsampleluminance": a sample brighter than the limit is scaled down to it
// (trading bias for fireflies); 0 means no limit.
Vec3f clampLuminance(Vec3f L, double limit) {
    const float y = luminance(L);
    return limit > 0 && y > limit ? float(limit / y) * L : L;
}

// pbrt-v4's maxcomponentvalue: a sample whose largest component (after the exposure `scale`) exceeds
// the limit is scaled down to it, keeping its colour.
Vec3f clampComponents(Vec3f L, double limit, double scale) {
    const float m = float(scale) * std::max({L.x, L.y, L.z});
    return limit > 0 && m > limit ? float(limit / m) * L : L;
}

Vec3f clamped(Vec3f L, const FilmSpec& film) {
    return clampComponents(clampLuminance(L, film.maxSampleLuminance), film.maxComponentValue, film.scale);
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += (s.empty() ? "" : "\n") + l;
    return s;
}

// Every random number of a pixel derives from this: an image is the same however tiles are spread.
std::uint64_t pixelSeed(std::uint64_t seed, int px, int py) {
    return hashCombine(seed, (std::uint64_t(py) << 32) | std::uint32_t(px));
}

}  // namespace

PreparedFrame::PreparedFrame(const RenderSettings& settings, const std::atomic<bool>* cancel)
    : start_(std::chrono::steady_clock::now()),
      settings_(checked(settings)),
      scene_(parseSceneFile(settings.scenePath, {settings.confined, settings.loadProgress})),
      arena_(threadCount(settings)),
      filter_(scene_.filter),
      filmColour_(scene_.film),
      shutter_(readShutter(scene_.camera.params)) {
    width_ = settings.width.value_or(scene_.film.xresolution);
    height_ = settings.height.value_or(scene_.film.yresolution);
    const std::string from = settings.width || settings.height ? "the render settings" : describe(scene_.film.where);
    if (width_ < 1 || height_ < 1 || width_ > kMaxSide || height_ > kMaxSide || (long long)width_ * height_ > kMaxPixels)
        throw SceneError(from + ": resolution " + std::to_string(width_) + "x" + std::to_string(height_) +
                         " is out of range (each side 1 to 16384 pixels, at most 64 Mpixels)");
    spp_ = settings.spp.value_or(scene_.pixelSamples);
    if (spp_ < 1 || spp_ > kMaxSpp)
        throw SceneError("samples per pixel " + std::to_string(spp_) + " out of range (1 to 1048576)");
    const std::array<double, 4> c = settings.crop.value_or(scene_.film.crop);
    if (!(c[0] >= 0 && c[0] < c[1] && c[1] <= 1 && c[2] >= 0 && c[2] < c[3] && c[3] <= 1))
        throw SceneError("crop window x0,x1,y0,y1 must satisfy 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1");
    // pbrt-v3's rounding of the crop window to pixels.
    area_ = {int(std::ceil(width_ * c[0])), int(std::ceil(height_ * c[2])), int(std::ceil(width_ * c[1])),
             int(std::ceil(height_ * c[3]))};
    if (area_.x1 <= area_.x0 || area_.y1 <= area_.y0) throw SceneError("the crop window holds no pixel");
    if (settings.sensor && settings.sensor->colourFilter && (area_.x1 - area_.x0 < 2 || area_.y1 - area_.y0 < 2))
        throw SceneError("a sensor's colour mosaic needs 2 x 2 pixels at least to demosaic; the crop window holds " +
                         std::to_string(area_.x1 - area_.x0) + " x " + std::to_string(area_.y1 - area_.y0));
    tiles_ = makeTiles(area_, settings.tileSize);
    scene_.film.crop = c;  // the camera prepares only the film radii this window covers

    // A sensor's pitch sets the film's size.
    if (settings_.sensor)
        if (auto d = sensorFilmDiagonalMm(*settings_.sensor, settings_.camera.filmDiagonal, width_, height_))
            settings_.camera.filmDiagonal = d;
    arena_.execute([&] {
        camera_ = makeCamera(scene_, settings_.camera, width_, height_, filter_.radius(), cancel);
        geometry_ = std::make_unique<SceneGeometry>(scene_);
    });
    if (settings_.sensor) {
        radiometry_ = camera_->filmRadiometry();
        if (!radiometry_)
            throw SceneError(sensorWithoutLens(scene_.camera.type));
    }
    integrator_ = makeIntegrator(*geometry_, scene_.integrator, scene_.camera.medium.get());
    spectral_ = settings.camera.spectral.value_or(camera_->spectral());
    arena_.execute([&] {
        flare_ = makeFlareLayer(*camera_, settings.camera, *geometry_, width_, height_, sensor_,
                                shutter_.moment(0, scene_.transformTimes), cancel);
    });
    const int byFilter = scene_.filter.type == FilterType::Box ? 1 : 3;
    wavelengths_ = spectral_ ? (settings.wavelengthsPerSample > 0 ? settings.wavelengthsPerSample : byFilter) : 0;
    setupSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::optional<RawMosaic> PreparedFrame::finishImage(const SplatBuffer& splats, Image& image,
                                                   std::map<std::string, std::string>& metadata) const {
    addSplats(splats, image);
    if (!settings_.sensor) return std::nullopt;
    double luminanceSum = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3)
        luminanceSum += luminance({image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]});
    // The film's values carry its exposure scale: the sensor sees the radiometric exposure.
    const SensorExposureInput input{radiometry_->exposurePerValue / scene_.film.scale, radiometry_->exposureSeconds,
                                    radiometry_->diagonalMm * 1e3 / std::hypot(double(width_), double(height_)),
                                    luminanceSum / double(std::size_t(image.width) * image.height)};
    const SensorCalibration calibration = calibrateSensor(*settings_.sensor, input);
    SensorReadout readout;
    arena_.execute([&] { readout = readOutSensor(*settings_.sensor, calibration, settings_.seed, area_.x0, area_.y0, image); });
    for (auto& [key, value] : describeSensor(*settings_.sensor, calibration, readout)) metadata[key] = value;
    if (readout.mosaic) readout.mosaic->description = metadata["sensor"];
    return std::move(readout.mosaic);
}

void PreparedFrame::addSplats(const SplatBuffer& splats, Image& image) const {
    const PixelRect& box = splats.box();
    const std::size_t boxWidth = std::size_t(box.x1 - box.x0);
    for (int y = std::max(box.y0, area_.y0); y < std::min(box.y1, area_.y1); ++y)
        for (int x = std::max(box.x0, area_.x0); x < std::min(box.x1, area_.x1); ++x) {
            const float* s = &splats.rgb()[(std::size_t(y - box.y0) * boxWidth + std::size_t(x - box.x0)) * 3];
            const Vec3f v = filmColour_({s[0], s[1], s[2]});
            float* p = &image.rgb[(std::size_t(y - area_.y0) * std::size_t(image.width) + std::size_t(x - area_.x0)) * 3];
            // Negative splats (HeroWavelengths.h: a wavelength taken from where it did not land) may
            // outweigh a pixel; the film clamps at zero as renderRect does.
            p[0] = std::max(0.0f, p[0] + v.x);
            p[1] = std::max(0.0f, p[1] + v.y);
            p[2] = std::max(0.0f, p[2] + v.z);
        }
}

bool PreparedFrame::renderRect(const PixelRect& rect, float* dst, std::size_t rowStride, TileCounters& counters,
                               SplatBuffer& splats, const std::atomic<bool>* cancel) const {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    TileCounters local;
    // Camera rays are made for a run of pixels at once: the lens trace vectorises only over batches
    // of several dozen rays (per ray 263 ns in batches of 16, 66 ns in batches of 64: bench/README.md).
    const int runPixels = std::max(1, kCameraBatchRays / spp_);
    std::vector<CameraSample> samples(std::size_t(runPixels) * spp_);
    std::vector<CameraRay> rays(samples.size());
    std::vector<float> filterWeights(samples.size());
    // Spectral: each sample's wavelengths (the first its own) and where each lands.
    const std::size_t spectralSlots = spectral_ ? samples.size() * wavelengths_ : 0;
    std::vector<WavelengthSample> wavelengths(spectralSlots);
    std::vector<double> wavelengthsNm(spectralSlots);
    std::vector<FilmLanding> landings(spectralSlots);
    SplatBuffer rowSplats;  // a row's, added to `splats` row by row (SplatBuffer.h)
    for (int py = rect.y0; py < rect.y1; ++py) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            counters += local;
            return false;
        }
        rowSplats.clear();
        float* row = dst + std::size_t(py - rect.y0) * rowStride;
        for (int runStart = rect.x0; runStart < rect.x1; runStart += runPixels) {
            const int runEnd = std::min(rect.x1, runStart + runPixels);
            for (int px = runStart; px < runEnd; ++px) {
                const PixelSampler sampler(pixelSeed(settings_.seed, px, py));
                const std::size_t first = std::size_t(px - runStart) * spp_;
                for (int s = 0; s < spp_; ++s) {
                    const PixelSample u = sampler(std::uint32_t(s));
                    float dx, dy;
                    filterWeights[first + s] = filter_.sample(u.filmX, u.filmY, dx, dy);
                    samples[first + s] = {px + 0.5 + dx, py + 0.5 + dy, u.lensU, u.lensV,
                                          shutter_.moment(u.time, scene_.transformTimes)};
                    if (spectral_) {
                        // The wavelengths lie 1 / n apart in the distribution: the pixel's stratified
                        // dimension places them within that period, so that its samples' sets together
                        // fill n x spp strata; which of them the ray is traced at (the hero) is uniform.
                        const std::size_t slot = (first + s) * wavelengths_;
                        Pcg32 hero(hashCombine(pixelSeed(settings_.seed, px, py), std::uint64_t(s)), 2);
                        const float which = std::min(std::floor(hero.uniform() * float(wavelengths_)), float(wavelengths_ - 1));
                        sensor_.sample((u.wavelength + which) / float(wavelengths_), wavelengths_, &wavelengths[slot]);
                        for (int k = 0; k < wavelengths_; ++k) wavelengthsNm[slot + k] = wavelengths[slot + k].nm;
                        samples[first + s].wavelengthNm = wavelengths[slot].nm;
                    }
                }
            }
            const std::size_t runSamples = std::size_t(runEnd - runStart) * spp_;
            if (spectral_)
                camera_->generateSpectralRays(samples.data(), runSamples, wavelengthsNm.data(), wavelengths_,
                                              rays.data(), landings.data());
            else
                camera_->generateRays(samples.data(), runSamples, rays.data());
            for (int px = runStart; px < runEnd; ++px) {
                const std::uint64_t seed = pixelSeed(settings_.seed, px, py);
                const std::size_t first = std::size_t(px - runStart) * spp_;
                FilteredPixel pixel;
                for (int s = 0; s < spp_; ++s) {
                    const CameraRay& ray = rays[first + s];
                    if (!(ray.weight > 0)) {
                        ++local.blockedCameraRays;
                        pixel.add(filterWeights[first + s], {});
                        continue;
                    }
                    const std::uint64_t sampleSeed = hashCombine(seed, std::uint64_t(s));
                    Pcg32 rng(sampleSeed);
                    const Vec3f L = integrator_->radiance(ray.origin, ray.direction, samples[first + s].time, rng,
                                                          local.raysTraced);
                    if (!spectral_) {
                        pixel.add(filterWeights[first + s], clamped(ray.weight * L, scene_.film));
                        continue;
                    }
                    const float weight = filterWeights[first + s];
                    const std::size_t slot = (first + s) * wavelengths_;
                    // A sample's splats count as one of the target pixel's spp samples; the limits
                    // of maxsampleluminance and maxcomponentvalue apply to what stays in its own.
                    const Vec3f own =
                        heroWavelengthEstimate(sensor_, filter_, area_, px, py, weight, L, &wavelengths[slot],
                                               &landings[slot], wavelengths_, 1.0f / float(spp_), rowSplats);
                    pixel.add(weight, clamped(own, scene_.film));
                }
                local.cameraRays += spp_;
                float* out = row + std::size_t(px - rect.x0) * 3;
                // A filter's negative lobes can push a pixel below zero; pbrt-v3 clamps it there too.
                Vec3f v = pixel.value();
                if (!flare_.rgb.empty()) {
                    const float* f = &flare_.rgb[(std::size_t(py) * width_ + px) * 3];
                    v += Vec3f{f[0], f[1], f[2]};
                }
                v = filmColour_(v);
                out[0] = std::max(0.0f, v.x);
                out[1] = std::max(0.0f, v.y);
                out[2] = std::max(0.0f, v.z);
            }
        }
        splats.add(rowSplats);
    }
    counters += local;
    return true;
}

std::map<std::string, std::string> PreparedFrame::metadata() const {
    std::map<std::string, std::string> m = camera_->describe();
    std::ostringstream crop;
    crop << area_.x0 << "," << area_.x1 << "," << area_.y0 << "," << area_.y1;
    m["scene"] = scene_.file;
    m["resolution"] = std::to_string(width_) + "x" + std::to_string(height_);
    m["cropPixels"] = crop.str();
    m["spp"] = std::to_string(spp_);
    m["seed"] = std::to_string(settings_.seed);
    static const char* kIntegrators[] = {"path", "directlighting", "whitted", "volpath"};
    m["integrator"] = std::string(kIntegrators[int(scene_.integrator.type)]) + " maxdepth " +
                      std::to_string(scene_.integrator.maxDepth);
    m["units"] = "world metres, lens millimetres";
    m["film"] = spectral_ ? "spectral: wavelengths per sample " + std::to_string(wavelengths_) +
                                " (hero-wavelength MIS through the lens), RGB radiance to "
                                "spectrum by Smits (1999), CIE 1931 matching functions (Wyman, Sloan & Shirley 2013 "
                                "fit), linear Rec. 709"
                          : "RGB, linear Rec. 709";
    if (!scene_.film.filename.empty()) m["filmFilename"] = scene_.film.filename;
    if (!flare_.description.empty()) m["lensFlare"] = flare_.description;
    if (!scene_.warnings.empty()) m["warnings"] = joinLines(scene_.warnings);
    return m;
}

}  // namespace lenslab
