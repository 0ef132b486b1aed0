#pragma once
// Cameras turn a film position (raster pixels of the full image, y down) and a 2D lens sample
// into a world-space ray and its weight (the film's response to radiance along it).
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Vec3f.h"

namespace lenslab {

struct CameraRay {
    Vec3f origin, direction;  // world, metres; direction unit length
    float weight = 0;         // 0: blocked by the lens
};

struct CameraSample {
    double rasterX = 0, rasterY = 0;
    float u1 = 0, u2 = 0;     // lens sample
    float time = 0;           // the ray's moment, a TransformTimes::fraction (core/AnimatedTransform.h)
    double wavelengthNm = 0;  // a spectral render's wavelength for this sample (0: none)
};

// Where a camera ray made at a sample's own (hero) wavelength meets the film at another of the
// sample's wavelengths, traced back through the lens (docs/spectral.md, "Several wavelengths per
// sample"). Densities are per unit of ray measure (etendue), so they compare across film points.
struct FilmLanding {
    double rasterX = 0, rasterY = 0;
    double density = 0;   // of the camera making this ray from that film point at that wavelength: 0
                          // when it cannot (the lens blocks it there, or it leaves the sampled pupil)
    double response = 0;  // the film's response there per unit radiance and ray measure (the exposure
                          // time, a shaped stop's transmission): a ray's weight is response / density
};

// A lens camera's film as a light meter sees it.
struct FilmRadiometry {
    double exposurePerValue = 0;  // focal-plane radiant exposure (scene radiance x sr x s) per film value
    double exposureSeconds = 1;   // the shutter's, included in exposurePerValue
    double diagonalMm = 0;        // the film's
};

class Camera {
public:
    virtual ~Camera() = default;
    // False when the lens blocks the ray (counted by the caller).
    virtual bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const = 0;
    // Many rays at once (a pixel's samples); blocked rays get weight 0. Lens cameras override this
    // to trace the lens as a structure-of-arrays batch.
    virtual void generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const {
        for (std::size_t i = 0; i < n; ++i)
            if (!generateRay(samples[i].rasterX, samples[i].rasterY, samples[i].u1, samples[i].u2, out[i])) out[i].weight = 0;
    }
    // Samples that carry `perSample` wavelengths each (wavelengthsNm[i * perSample + k]; k = 0 is
    // the sample's own, as in samples[i].wavelengthNm): rays made at the sample's own wavelength
    // into out, and landings[i * perSample + k], where the ray meets the film at wavelength k. A
    // camera without dispersion lands every wavelength on the sample's own film point.
    virtual void generateSpectralRays(const CameraSample* samples, std::size_t n, const double* wavelengthsNm,
                                      int perSample, CameraRay* out, FilmLanding* landings) const {
        (void)wavelengthsNm;
        generateRays(samples, n, out);
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < perSample; ++k)
                landings[i * perSample + k] = {samples[i].rasterX, samples[i].rasterY, 1.0, double(out[i].weight)};
    }
    // Whether its rays depend on each sample's wavelength (a lens traced with dispersion): the
    // frame is then rendered spectrally unless told otherwise.
    virtual bool spectral() const { return false; }
    // What a sensor behind the film collects (film/SensorReadout.h); none for a camera without a
    // lens, whose film values are radiance, not exposure.
    virtual std::optional<FilmRadiometry> filmRadiometry() const { return std::nullopt; }
    // Camera and lens parameters for the image metadata.
    virtual std::map<std::string, std::string> describe() const = 0;
    // What the camera knows its picture will not show (a lens's image circle smaller than the film),
    // in words for the render's warnings; none for a camera without a lens.
    virtual std::vector<std::string> warnings() const { return {}; }
};

}  // namespace lenslab
