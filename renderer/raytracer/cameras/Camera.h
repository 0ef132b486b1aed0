#pragma once
// Cameras turn a film position (raster pixels of the full image, y down) and a 2D lens sample
// into a world-space ray and its weight (the film's response to radiance along it).
#include <cstddef>
#include <map>
#include <memory>
#include <string>

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
    // Whether its rays depend on each sample's wavelength (a lens traced with dispersion): the
    // frame is then rendered spectrally unless told otherwise.
    virtual bool spectral() const { return false; }
    // Camera and lens parameters for the image metadata.
    virtual std::map<std::string, std::string> describe() const = 0;
};

}  // namespace lenslab
