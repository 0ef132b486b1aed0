#pragma once
// pbrt-v3's "orthographic" camera: parallel rays along +z from the screen window (scene units),
// with an optional thin lens (lensradius, focaldistance) for depth of field.
#include "cameras/Camera.h"
#include "cameras/ScreenWindow.h"
#include "core/Transform.h"

namespace lenslab {

struct OrthographicParams {
    ScreenWindow screen{-1, 1, -1, 1};
    double lensRadius = 0;       // scene units; 0 = sharp everywhere
    double focalDistance = 1e6;  // scene units, along the view axis
};

class OrthographicCamera : public Camera {
public:
    OrthographicCamera(const OrthographicParams& params, const Transform& cameraToWorld, int width, int height);
    bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const override;
    std::map<std::string, std::string> describe() const override;

private:
    OrthographicParams params_;
    Transform cameraToWorld_;
    int width_, height_;
};

}  // namespace lenslab
