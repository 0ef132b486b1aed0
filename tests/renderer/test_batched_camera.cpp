// The realistic camera's batched path (generateRays: the exact trace as one structure-of-arrays
// batch) gives the same rays, bit for bit, as making them one by one (generateRay).
#include <gtest/gtest.h>

#include <cstring>

#include "cameras/RealisticCamera.h"
#include "sampling/Sampling.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

void expectBatchEqualsScalar(LensMode mode, const std::string& lens, std::optional<double> fstop = std::nullopt,
                             double autoThresholdPixels = 0.5) {
    RealisticParams p = realisticParams(test::lensPath(lens), fstop, 5000);
    p.mode = mode;
    p.autoThresholdPixels = autoThresholdPixels;
    const int width = 96, height = 64;
    const RealisticCamera camera(p, Transform{}, width, height, 0.5);
    if (mode == LensMode::Auto) {
        EXPECT_TRUE(camera.lensModes().usesThick() && camera.lensModes().usesExact()) << camera.lensModes().describe();
    }
    // A whole frame's samples, pixel by pixel, as the renderer draws them.
    std::vector<CameraSample> samples;
    for (int py = 0; py < height; py += 3)
        for (int px = 0; px < width; px += 2) {
            const PixelSampler sampler(mix64((std::uint64_t(py) << 32) | std::uint32_t(px)));
            for (std::uint32_t s = 0; s < 16; ++s) {
                const PixelSample u = sampler(s);
                samples.push_back({px + u.filmX, py + u.filmY, u.lensU, u.lensV});
            }
        }
    std::vector<CameraRay> batched(samples.size());
    camera.generateRays(samples.data(), samples.size(), batched.data());
    std::size_t passed = 0, differ = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        CameraRay one;
        if (!camera.generateRay(samples[i].rasterX, samples[i].rasterY, samples[i].u1, samples[i].u2, one)) one.weight = 0;
        if (!(one.weight > 0)) {
            differ += batched[i].weight != 0;
            continue;
        }
        ++passed;
        differ += std::memcmp(&one.origin, &batched[i].origin, sizeof(Vec3f)) != 0 ||
                  std::memcmp(&one.direction, &batched[i].direction, sizeof(Vec3f)) != 0 ||
                  std::memcmp(&one.weight, &batched[i].weight, sizeof(float)) != 0;
    }
    EXPECT_EQ(differ, 0u) << lensModeName(mode) << " " << lens;
    EXPECT_GT(passed, samples.size() / 2) << "most rays pass: the comparison compared rays";
}

TEST(BatchedCamera, AccurateRaysEqualScalarRaysBitForBit) {
    for (const char* lens : {"dgauss.50mm.dat", "wide.22mm.dat", "telephoto.250mm.dat", "fisheye.10mm.dat"})
        expectBatchEqualsScalar(LensMode::Exact, lens);
}

TEST(BatchedCamera, AutoAndApproximateRaysEqualScalarRaysBitForBit) {
    // Split by film radius: thick at the centre, exact at the rim.
    expectBatchEqualsScalar(LensMode::Auto, "telephoto.250mm.dat", 11, 0.07);
    expectBatchEqualsScalar(LensMode::Thick, "dgauss.50mm.dat");
}

}  // namespace
}  // namespace lenslab
