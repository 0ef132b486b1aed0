// Sphere lights seen from outside are sampled by the cone they subtend: the irradiance estimate
// under a small sphere overhead is nearly noiseless and equals pi L sin^2(theta max).
#include <gtest/gtest.h>

#include <cmath>

#include "lights/AreaLight.h"
#include "scene/SceneDescription.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

std::shared_ptr<const Shape> sphereAt(const std::string& placement) {
    test::TempDir dir;
    const SceneDescription s = parseSceneFile(dir.write("s.pbrt", "Camera \"perspective\"\nWorldBegin\n" + placement +
                                                                      "\nShape \"sphere\" \"float radius\" 0.5\nWorldEnd\n"));
    return s.shapes.at(0).shape;
}

TEST(SphereLight, ConeSamplingGivesTheClosedFormIrradianceWithLittleNoise) {
    const auto light = makeDiffuseAreaLight(sphereAt("Translate 0 0 5"), 0, {1, 1, 1}, false);
    const double expected = M_PI * 0.25 / 25;  // pi L sin^2(theta max), sin(theta max) = r / d
    const int n = 4096;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        LightSample s;
        ASSERT_TRUE(light->sample({0, 0, 0}, (i + 0.5f) / n, float((i * 0.618034) - std::floor(i * 0.618034)), s));
        // The sample lies on the sphere's near side and the pdf is the one pdf() gives for it.
        const Vec3f q = s.distance * s.wi;
        EXPECT_NEAR(length(q - Vec3f{0, 0, 5}), 0.5f, 1e-4f);
        EXPECT_LT(q.z, 5.0f);
        SurfaceHit at;
        at.p = q;
        at.ng = normalize(q - Vec3f{0, 0, 5});
        EXPECT_NEAR(light->pdf({0, 0, 0}, s.wi, &at), s.pdf, 1e-3f * s.pdf);
        const double e = s.radiance.x * s.wi.z / s.pdf;
        sum += e;
        sum2 += e * e;
    }
    const double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
    EXPECT_NEAR(mean, expected, 1e-3 * expected);
    EXPECT_LT(sd, 0.01 * expected);  // by area, about half the samples would miss (the far side)
}

TEST(SphereLight, FromInsideAReversedSphereItIsSampledByArea) {
    const auto light = makeDiffuseAreaLight(sphereAt("ReverseOrientation"), 0, {1, 1, 1}, false);
    // Inside a sphere lit on its inner side the radiance is L in every direction: E = pi L.
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        LightSample s;
        if (light->sample({0, 0, 0}, (i + 0.5f) / n, float((i * 0.618034) - std::floor(i * 0.618034)), s) && s.wi.z > 0)
            sum += s.radiance.x * s.wi.z / s.pdf;
    }
    EXPECT_NEAR(sum / n, M_PI, 0.02 * M_PI);
}

}  // namespace
}  // namespace lenslab
