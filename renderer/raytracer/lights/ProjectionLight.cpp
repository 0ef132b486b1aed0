// pbrt-v3's projection light: a slide projector at the light-space origin looking down +z. The
// image spans [-aspect, aspect] x [-1, 1] on the plane z = 1 / tan(fov / 2) (or [-1, 1] x
// [-1/aspect, 1/aspect] for a tall image); its top row meets light-space -y, as in pbrt-v3.
#include <cmath>

#include "lights/ImageLights.h"
#include "lights/PointLight.h"

namespace lenslab {

namespace {

class ProjectionLight : public PointLight {
public:
    ProjectionLight(std::optional<LinearImage> image, Vec3f intensity, float fovDegrees, const Transform& lightToWorld)
        : PointLight(transformPoint(lightToWorld, {0, 0, 0}), intensity), image_(std::move(image)),
          toLight_(inverse(lightToWorld)) {
        const float aspect = image_ ? float(image_->width) / float(image_->height) : 1.0f;
        halfX_ = aspect > 1 ? aspect : 1.0f;
        halfY_ = aspect > 1 ? 1.0f : 1.0f / aspect;
        tanHalfFov_ = std::tan(fovDegrees * float(M_PI) / 360.0f);
        const float tanDiagonal = tanHalfFov_ * std::sqrt(1.0f + 1.0f / (aspect * aspect));
        cosTotal_ = std::cos(std::atan(tanDiagonal));
    }
    // pbrt-v3's: the cone around the image's diagonal, weighted by the image's mean.
    Vec3f power() const override {
        const Vec3f mean = image_ ? image_->average() : Vec3f{1, 1, 1};
        return 2.0f * float(M_PI) * (1.0f - cosTotal_) * intensity_ * mean;
    }

protected:
    Vec3f directionalScale(Vec3f w) const override {
        const Vec3f d = normalize(transformVector(toLight_, w));
        if (d.z < 1e-3f) return {};  // behind the projector
        const float x = d.x / (d.z * tanHalfFov_), y = d.y / (d.z * tanHalfFov_);
        if (std::fabs(x) > halfX_ || std::fabs(y) > halfY_) return {};
        if (!image_) return {1, 1, 1};
        return image_->lookup((x + halfX_) / (2.0f * halfX_), (y + halfY_) / (2.0f * halfY_));
    }

private:
    std::optional<LinearImage> image_;
    Transform toLight_;
    float halfX_, halfY_, tanHalfFov_, cosTotal_;
};

}  // namespace

std::unique_ptr<Light> makeProjectionLight(std::optional<LinearImage> image, Vec3f intensity, float fovDegrees,
                                           const Transform& lightToWorld) {
    return std::make_unique<ProjectionLight>(std::move(image), intensity, fovDegrees, lightToWorld);
}

}  // namespace lenslab
