#include "cameras/EnvironmentCamera.h"

#include <cmath>

namespace lenslab {

EnvironmentCamera::EnvironmentCamera(const Transform& cameraToWorld, int width, int height)
    : cameraToWorld_(cameraToWorld), width_(width), height_(height) {}

bool EnvironmentCamera::generateRay(double rasterX, double rasterY, float, float, CameraRay& out) const {
    const double theta = M_PI * rasterY / height_, phi = 2 * M_PI * rasterX / width_;
    const Vec3f dir{float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi))};
    out.origin = transformPoint(cameraToWorld_, {0, 0, 0});
    out.direction = normalize(transformVector(cameraToWorld_, dir));
    out.weight = 1;
    return true;
}

std::map<std::string, std::string> EnvironmentCamera::describe() const { return {{"camera", "environment"}}; }

}  // namespace lenslab
