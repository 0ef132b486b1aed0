#include "cameras/PerspectiveCamera.h"

#include <cmath>

#include "sampling/Sampling.h"

namespace lenslab {

PerspectiveCamera::PerspectiveCamera(const PerspectiveParams& params, const Transform& cameraToWorld, int width,
                                     int height)
    : params_(params), cameraToWorld_(cameraToWorld), width_(width), height_(height),
      tanHalf_(std::tan(params.fovDegrees * M_PI / 360.0)), screen_(ScreenWindow::forImage(width, height)) {}

bool PerspectiveCamera::generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const {
    // Camera space (pbrt): +x right, +y up, +z forward.
    double sx, sy;
    screen_.toScreen(rasterX, rasterY, width_, height_, sx, sy);
    Vec3f dir{float(sx * tanHalf_), float(sy * tanHalf_), 1.0f};
    Vec3f origin{0, 0, 0};
    if (params_.lensRadius > 0) {
        float lx, ly;
        concentricDisk(u1, u2, lx, ly);
        const Vec3f focus = float(params_.focalDistance) * dir;
        origin = {float(params_.lensRadius) * lx, float(params_.lensRadius) * ly, 0};
        dir = focus - origin;
    }
    out.origin = transformPoint(cameraToWorld_, origin);
    out.direction = normalize(transformVector(cameraToWorld_, dir));
    out.weight = 1;
    return true;
}

std::map<std::string, std::string> PerspectiveCamera::describe() const {
    return {{"camera", "perspective"},
            {"fovDegrees", std::to_string(params_.fovDegrees)},
            {"lensRadiusM", std::to_string(params_.lensRadius)},
            {"focalDistanceM", std::to_string(params_.focalDistance)}};
}

}  // namespace lenslab
