#pragma once
// Lens flare: the ghosts of bright emitters, rendered from the prescription (Hullin, Eisemann,
// Seidel & Lee, "Physically-based real-time lens flare rendering", SIGGRAPH 2011). Each
// two-reflection path (optics/trace/GhostPath.h) is traced exactly through its unfolded lens for a
// grid of rays over the part of the entrance that reaches the stop, with the coatings' reflectance
// and transmittance at every surface per wavelength and angle; the grid lands on the film as a
// mesh whose cells spread the light they carry over their area, cut per pixel by the stop's shape
// (aperture blades give polygons) and by every clear aperture the path meets. The paraxial model
// (Lee & Eisemann, "Practical real-time lens-flare rendering", EGSR 2013) maps the stop's opening
// onto the film by the path's ray-transfer matrices instead: one uniform, aperture-shaped patch,
// cut by each clear aperture of the path as the matrices map it into the stop's plane (a circle).
//
// Spectral: the geometry is traced in three wavebands and the coatings evaluated at four
// wavelengths in each, so ghosts take the colours of their coatings (and their fringes from the
// glasses' dispersion). The result is an image layer the frame adds to its pixels: the same for
// any tiling, thread count or process.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "cameras/GhostSelection.h"
#include "cameras/RealisticCamera.h"
#include "core/Vec3f.h"
#include "trace/GhostPath.h"

namespace lenslab {

// The wavelengths the coatings are evaluated at (nm), four per waveband, and the waveband each
// belongs to. A source's light is given per wavelength (FlareSource::rgbPerWavelength) as the film's
// response to its share of the spectrum: their sum is the source's RGB.
constexpr int kFlareWavebands = 3, kFlareWavelengthsPerBand = 4;
constexpr int kFlareWavelengths = kFlareWavebands * kFlareWavelengthsPerBand;
double flareWavelengthNm(int k);      // 395, 425, ..., 725
double flareWavelengthEdgeNm(int k);  // the lower edge of wavelength k's share (k = 12: the upper end)

// A bright emitter as the lens sees it, in lens space (mm, +z toward the scene).
struct FlareSource {
    Vec3 direction;        // unit, from the lens's front vertex toward the source
    double distanceMm = 0; // 0: distant (a direction only)
    // The irradiance it casts on a plane facing it at the front vertex, as RGB per flare wavelength.
    std::array<Vec3f, kFlareWavelengths> rgbPerWavelength{};
    std::string what;      // for the statistics: "point light", "distant light", ...
};

struct FlareStats {
    int sources = 0, paths = 0;
    std::uint64_t raysTraced = 0;
    double seconds = 0;  // wall-clock of the whole layer
};

// The flare layer of a frame: RGB per pixel of the full image (width x height), values on the
// camera's own scale (irradiance times its weighting). `paths` are the ghosts to render. Uses the
// calling thread's TBB arena. A set *cancel throws RenderCancelled within one ghost's trace: a lens
// of 80 surfaces has 3,160 ghosts, minutes of work.
std::vector<float> renderLensFlare(const RealisticCamera& camera, int width, int height,
                                   const std::vector<FlareSource>& sources, const std::vector<GhostPath>& paths,
                                   GhostModel model, FlareStats& stats, const std::atomic<bool>* cancel = nullptr);

// The ghosts of the camera's lens to render: all of them, or the brightest `count` by the ghost
// analysis at the camera's aperture and focus. A set *cancel throws RenderCancelled.
std::vector<GhostPath> selectGhostPaths(const RealisticCamera& camera, const GhostSelection& selection,
                                        const std::atomic<bool>* cancel = nullptr);

// The exact model's grid of rays across the entrance, per side (grid^2 cells per path, waveband
// and source).
constexpr int kFlareGrid = 48;

}  // namespace lenslab
