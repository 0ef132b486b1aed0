#pragma once
// Helpers for light and integrator tests: a parsed scene with its geometry and an integrator, to
// measure the radiance along chosen rays; image files written through OpenImageIO; lights made
// straight from parameters.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "integrators/Integrator.h"
#include "lights/Light.h"
#include "scene/SceneDescription.h"
#include "geometry/SceneGeometry.h"
#include "SceneParams.h"
#include "TempDir.h"

namespace lenslab::test {

// Camera and film lines every test scene starts with (the probes trace their own rays).
inline const char* kProbeHeader = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                                  "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\n";

// A uniform white sky, radiance 1.
inline const char* kWhiteSky = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";

// A scene file in `dir` that the probes trace into: `options` (before the camera), the header, and
// `world` between WorldBegin and WorldEnd.
inline std::string probeScene(const TempDir& dir, const std::string& world, const std::string& options = "") {
    return dir.write("s.pbrt", options + kProbeHeader + "WorldBegin\n" + world + "WorldEnd\n");
}

// Each channel of `got` within `tolerance` of `expected`, as a ratio.
inline void expectRelative(Vec3f got, Vec3f expected, double tolerance, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c] / expected[c], 1.0, tolerance) << what << " channel " << c;
}

class RadianceProbe {
public:
    RadianceProbe(const std::string& scenePath, IntegratorType type, int maxDepth)
        : scene_(parseSceneFile(scenePath)), geometry_(std::make_unique<SceneGeometry>(scene_)),
          integrator_(makeIntegrator(*geometry_, IntegratorSpec{type, maxDepth}, scene_.camera.medium.get())) {}

    // One estimate along the ray; `sample` picks an independent random stream.
    Vec3f once(Vec3f origin, Vec3f direction, std::uint64_t sample) const {
        Pcg32 rng(hashCombine(0x5eed, sample));
        std::uint64_t rays = 0;
        return integrator_->radiance(origin, normalize(direction), 0, rng, rays);
    }
    // The mean of n estimates, as luminance.
    double mean(Vec3f origin, Vec3f direction, int n) const {
        double sum = 0;
        for (int i = 0; i < n; ++i) sum += luminance(once(origin, direction, std::uint64_t(i)));
        return sum / n;
    }
    const SceneGeometry& geometry() const { return *geometry_; }

private:
    SceneDescription scene_;
    std::unique_ptr<SceneGeometry> geometry_;
    std::unique_ptr<Integrator> integrator_;
};

// Writes RGB float pixels (row-major, top row first) as `path`; the format follows the extension,
// stored as 8-bit where the format is (PNG). In RadianceProbe.cpp: OpenImageIO's headers cost each
// file that includes them 4 CPU seconds to compile.
void writeImage(const std::string& path, int width, int height, const std::vector<float>& rgb);

// A light from `LightSource "type"` with the given parameters, under `lightToWorld`.
inline std::unique_ptr<Light> lightFrom(const std::string& type, std::vector<Param> params,
                                        const Transform& lightToWorld = {}) {
    std::vector<std::string> warnings;
    const ParamSet p(SourceLocation{"test", 1, "LightSource \"" + type + "\""}, std::move(params));
    return makeLight(type, p, lightToWorld, SceneDialect::PbrtV3, [](const std::string& name, const SourceLocation&) { return name; },
                     warnings);
}

}  // namespace lenslab::test
