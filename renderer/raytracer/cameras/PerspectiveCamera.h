#pragma once
// pbrt-v3's "perspective" camera: a pinhole, or a thin lens with lensradius/focaldistance (metres).
#include "cameras/Camera.h"
#include "cameras/ScreenWindow.h"
#include "core/Transform.h"

namespace lenslab {

struct PerspectiveParams {
    double fovDegrees = 90;   // across the shorter image side
    double lensRadius = 0;    // metres; 0 = pinhole
    double focalDistance = 1e6;  // metres, along the view axis
};

class PerspectiveCamera : public Camera {
public:
    PerspectiveCamera(const PerspectiveParams& params, const Transform& cameraToWorld, int width, int height);
    bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const override;
    std::map<std::string, std::string> describe() const override;

private:
    PerspectiveParams params_;
    Transform cameraToWorld_;
    int width_, height_;
    double tanHalf_;
    ScreenWindow screen_;  // the shorter image side spans [-1, 1]
};

}  // namespace lenslab
