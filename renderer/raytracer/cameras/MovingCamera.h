#pragma once
// A camera that moves during the exposure (its CameraToWorld differs at the two TransformTimes): the
// lens or pinhole makes each ray in camera space, and the ray is carried into the world by the
// camera's transform at that ray's own moment.
#include <memory>

#include "cameras/Camera.h"
#include "core/AnimatedTransform.h"

namespace lenslab {

class MovingCamera : public Camera {
public:
    // `still` is the camera built with its CameraToWorld the identity.
    MovingCamera(std::unique_ptr<Camera> still, const AnimatedTransform& cameraToWorld);
    // A lone ray carries no moment: it leaves at shutter open.
    bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const override;
    void generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const override;
    void generateSpectralRays(const CameraSample* samples, std::size_t n, const double* wavelengthsNm, int perSample,
                              CameraRay* out, FilmLanding* landings) const override;
    bool spectral() const override { return still_->spectral(); }
    std::optional<FilmRadiometry> filmRadiometry() const override { return still_->filmRadiometry(); }
    std::map<std::string, std::string> describe() const override;

private:
    void toWorldAtTheirMoments(const CameraSample* samples, std::size_t n, CameraRay* out) const;
    std::unique_ptr<Camera> still_;
    AnimatedTransform cameraToWorld_;
};

}  // namespace lenslab
