#pragma once
// pbrt-v3's "environment" camera: the whole sphere of directions around the camera as a latitude-
// longitude image (x across 360 degrees of azimuth, y from the +y pole down to the -y pole).
#include "cameras/Camera.h"
#include "core/Transform.h"

namespace lenslab {

class EnvironmentCamera : public Camera {
public:
    EnvironmentCamera(const Transform& cameraToWorld, int width, int height);
    bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const override;
    std::map<std::string, std::string> describe() const override;

private:
    Transform cameraToWorld_;
    int width_, height_;
};

}  // namespace lenslab
