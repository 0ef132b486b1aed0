#include "cameras/OrthographicCamera.h"

#include "sampling/Sampling.h"

namespace lenslab {

OrthographicCamera::OrthographicCamera(const OrthographicParams& params, const Transform& cameraToWorld, int width,
                                       int height)
    : params_(params), cameraToWorld_(cameraToWorld), width_(width), height_(height) {}

bool OrthographicCamera::generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const {
    double sx, sy;
    params_.screen.toScreen(rasterX, rasterY, width_, height_, sx, sy);
    Vec3f origin{float(sx), float(sy), 0};
    Vec3f dir{0, 0, 1};
    if (params_.lensRadius > 0) {
        // Every ray through the lens meets the pinhole ray on the plane of focus.
        float lx, ly;
        concentricDisk(u1, u2, lx, ly);
        const Vec3f focus = origin + float(params_.focalDistance) * dir;
        origin = origin + Vec3f{float(params_.lensRadius) * lx, float(params_.lensRadius) * ly, 0};
        dir = normalize(focus - origin);
    }
    out.origin = transformPoint(cameraToWorld_, origin);
    out.direction = normalize(transformVector(cameraToWorld_, dir));
    out.weight = 1;
    return true;
}

std::map<std::string, std::string> OrthographicCamera::describe() const {
    const ScreenWindow& s = params_.screen;
    return {{"camera", "orthographic"},
            {"screenWindow", std::to_string(s.x0) + "," + std::to_string(s.x1) + "," + std::to_string(s.y0) + "," +
                                 std::to_string(s.y1)},
            {"lensRadius", std::to_string(params_.lensRadius)},
            {"focalDistance", std::to_string(params_.focalDistance)}};
}

}  // namespace lenslab
