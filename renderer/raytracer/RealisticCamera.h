#pragma once
// The realistic camera of Kolb, Mitchell & Hanrahan (1995): rays from the film through a real lens
// (exact trace, "accurate") or its thick-lens model ("approximate"). Lens space is millimetres with
// the origin at the front vertex and +z toward the scene, like pbrt's camera space; a lens-space
// ray leaving the front element maps to camera space by dividing by 1000 (metres).
#include <optional>
#include <string>

#include "Camera.h"
#include "ExitPupilBounds.h"
#include "LensAnalysis.h"
#include "Transform.h"

namespace lenslab {

struct RealisticParams {
    std::string lensPath;
    std::optional<double> fstop;           // nullopt: the widest (unless stopDiameterMm is set)
    std::optional<double> stopDiameterMm;  // pbrt-v3's aperturediameter: the stop opening itself
    double focusDistanceMm = 10000;        // front vertex to the plane of focus
    bool focusFromFilm = false;            // pbrt-v3: focusDistanceMm is measured from the film instead
    double filmDiagonalMm = 35;
    bool approximate = false;              // thick-lens model instead of the exact trace
    double exposureTime = 1;               // seconds the shutter is open
    bool simpleWeighting = false;          // pbrt-v3: weights normalised to 1 at the image centre
};

class RealisticCamera : public Camera {
public:
    // Throws OpticsError (range violations name the range) and LensTableError.
    // filmMarginPixels: how far beyond the image the pixel filter reaches.
    RealisticCamera(const RealisticParams& params, const Transform& cameraToWorld, int width, int height,
                    double filmMarginPixels);
    bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const override;
    void generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const override;
    std::map<std::string, std::string> describe() const override;

    const LensAnalysis& analysis() const { return analysis_; }
    double filmZ() const { return filmZ_; }  // mm, lens space
    const ExitPupilBounds& pupilBounds() const { return bounds_; }
    // The film point (mm, lens space z = filmZ) a raster position maps to; the lens inverts the
    // image, so the top-left pixel sits at +x, -y (pbrt's camera x points right, y up).
    void filmPoint(double rasterX, double rasterY, double& x, double& y) const;

private:
    // Where a film ray is aimed and the weight it will carry if the lens passes it (0: no aim).
    double aim(double rasterX, double rasterY, float u1, float u2, Ray& ray) const;
    bool finish(const Ray& lensRay, double weight, CameraRay& out) const;

    RealisticParams params_;
    Transform cameraToWorld_;
    int width_, height_;
    double halfWidthMm_, halfHeightMm_;
    LensAnalysis analysis_;
    double filmZ_ = 0;
    ExitPupilBounds bounds_;         // accurate mode
    double weightScale_ = 1;         // exposure time, or 1 / centre weight for simple weighting
};

}  // namespace lenslab
