#include "cameras/MovingCamera.h"

namespace lenslab {

namespace {

void toWorld(const Transform& cameraToWorld, CameraRay& ray) {
    ray.origin = transformPoint(cameraToWorld, ray.origin);
    ray.direction = normalize(transformVector(cameraToWorld, ray.direction));
}

}  // namespace

MovingCamera::MovingCamera(std::unique_ptr<Camera> still, const AnimatedTransform& cameraToWorld)
    : still_(std::move(still)), cameraToWorld_(cameraToWorld) {}

bool MovingCamera::generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const {
    if (!still_->generateRay(rasterX, rasterY, u1, u2, out)) return false;
    toWorld(cameraToWorld_.start(), out);
    return true;
}

void MovingCamera::generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const {
    still_->generateRays(samples, n, out);
    toWorldAtTheirMoments(samples, n, out);
}

// The landings are film positions and densities, the same in camera space and in the world.
void MovingCamera::generateSpectralRays(const CameraSample* samples, std::size_t n, const double* wavelengthsNm,
                                        int perSample, CameraRay* out, FilmLanding* landings) const {
    still_->generateSpectralRays(samples, n, wavelengthsNm, perSample, out, landings);
    toWorldAtTheirMoments(samples, n, out);
}

void MovingCamera::toWorldAtTheirMoments(const CameraSample* samples, std::size_t n, CameraRay* out) const {
    for (std::size_t i = 0; i < n; ++i)
        if (out[i].weight > 0) toWorld(cameraToWorld_.at(samples[i].time), out[i]);
}

std::map<std::string, std::string> MovingCamera::describe() const {
    auto d = still_->describe();
    d["cameraMotion"] = "moves during the exposure";
    return d;
}

}  // namespace lenslab
