#pragma once
// The ray tracer's entry point: a scene file in, an image (and its statistics) out.
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "film/SensorSpec.h"
#include "settings/LensSettings.h"
#include "prescription/LensTable.h"

namespace lenslab {

// Overrides of the scene's Camera "realistic" parameters (the command line's and the server's);
// unset = as in the scene. Millimetres. Settings carry their source for messages ("--fstop").
struct CameraOverrides {
    std::optional<std::string> lensFile;   // instead of the scene's specfile / lensfile
    std::optional<TableLayout> lensLayout; // the layout lensFile was checked with (uploads)
    std::optional<Setting> fstop;
    std::optional<Setting> focusDistance;  // front vertex to the plane of focus
    std::optional<Setting> wavelength;     // nm: the lens traced at one wavelength (default its primary)
    std::optional<double> filmDiagonal;
    std::optional<std::string> mode;       // "exact" | "thick" | "auto"
    // Not a scene parameter: render spectrally (a wavelength per sample, the lens's dispersion, the
    // film through the colour matching functions) or in RGB. Unset: spectral when the lens disperses
    // and no single wavelength is asked for.
    std::optional<bool> spectral;
    // Lens flare (renderer/raytracer/cameras/GhostSelection.h): which ghosts ("off", "auto", "all",
    // or N, the brightest N) and their model ("exact", "paraxial"); unset: the scene camera's
    // "ghosts" and "ghostmodel" (off and exact when it has none).
    std::optional<std::string> ghosts, ghostModel;
    // The lens tilted (about the body's x axis), swung (about its y axis), in degrees, and shifted
    // across the film (x, y mm): a tilt-shift lens (renderer/raytracer/cameras/LensMount.h).
    std::optional<double> tiltDegrees, swingDegrees;
    std::optional<std::array<double, 2>> shiftMm;
};

struct RenderSettings {
    std::string scenePath;                 // pbrt-v3 subset
    bool confined = false;                 // the scene may only name files inside its folder (HTTP)
    std::function<void(double)> loadProgress;  // fraction of the scene file read, while parsing
    CameraOverrides camera;
    std::optional<int> spp, width, height; // unset = as in the scene
    int threads = 0;                       // 0 = all cores
    int tileSize = 32;
    std::uint64_t seed = 0;
    // A spectral render's wavelengths per camera sample, 1 to 8 (docs/spectral.md): the first is the
    // sample's own, the others share its scene path. 1 is the plain one-wavelength sample; 0 picks
    // 3 for smooth pixel filters and 1 for the box, whose hard borders make the other wavelengths
    // noisier than they save (bench/README.md).
    int wavelengthsPerSample = 0;
    // Crop window x0, x1, y0, y1 as fractions of the image (pbrt's cropwindow); unset = the scene's.
    // The output image holds only the cropped pixels.
    std::optional<std::array<double, 4>> crop;
    // A real camera sensor behind the film (film/SensorSpec.h, docs/sensor.md); unset: the noiseless film.
    std::optional<SensorSpec> sensor;
};

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // linear, row-major, top row first
};

struct TileUpdate {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixel rectangle [x0, x1) x [y0, y1) just finished
    int tilesDone = 0, tilesTotal = 0;
};

struct RenderStats {
    double setupSeconds = 0;   // scene load, camera setup (pupil bounds, focus)
    double renderSeconds = 0;
    std::uint64_t cameraRays = 0, blockedCameraRays = 0, raysTraced = 0;
    // Lens flare, part of the setup: emitters and ghost paths rendered, rays traced for them, seconds.
    int flareSources = 0, flarePaths = 0;
    std::uint64_t flareRays = 0;
    double flareSeconds = 0;
};

struct RenderOutput {
    Image image;
    RenderStats stats;
    std::map<std::string, std::string> metadata;  // camera and lens parameters, for EXR headers
    std::optional<RawMosaic> raw;  // a sensor's ADC numbers when it has a colour mosaic (a .dng output's)
    // What the picture does not show of the scene, in words (render/RenderWarnings.h): the lens
    // blocking most camera rays, an image circle smaller than the film. Also in the EXR header
    // (lenslab.renderWarnings).
    std::vector<std::string> warnings;
};

// Scene problems (file, line, directive) and bad settings.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class RenderCancelled : public std::runtime_error {
public:
    RenderCancelled() : std::runtime_error("render cancelled") {}
};

// Renders the scene. onTile is called (from worker threads, serialised) after each finished tile
// with the image so far. Throws SceneError, OpticsError, RenderCancelled when *cancel turns true.
RenderOutput renderScene(const RenderSettings& settings,
                         const std::function<void(const TileUpdate&, const Image&)>& onTile = {},
                         const std::atomic<bool>* cancel = nullptr);

// The checks of the scene's camera and the settings' overrides that renderScene makes before its
// setup (the options block read, a realistic camera's lens, aperture and focus checked; the world
// not loaded): throws the SceneError renderScene would, in milliseconds, so a request can be
// refused before it is queued.
void checkRenderSettings(const RenderSettings& settings);

// PNG: sRGB tone-mapped with an exposure scale. EXR: linear float RGB, tiled, metadata in the header.
std::vector<std::uint8_t> encodePng(const Image& image, double exposure = 1.0);
std::vector<std::uint8_t> encodeExr(const RenderOutput& output);
// A path's extension, lower case (".exr"): the format writeImageFile writes.
std::string imageFileExtension(const std::string& path);
// Writes .png, .exr or .dng (the raw mosaic, film/DngFile.h; std::invalid_argument without one) by
// the path's extension, atomically (temporary file, then rename).
void writeImageFile(const RenderOutput& output, const std::string& path, double exposure = 1.0);

}  // namespace lenslab
