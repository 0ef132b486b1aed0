// A perspective camera without "fov" sees 90 degrees across the image's shorter side, pbrt-v3's
// default: the ray through the middle of that side's edge leaves at 45 degrees to the axis.
#include <gtest/gtest.h>

#include "cameras/CameraFactory.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// The camera ray through raster point (x, y) of a width x height film, camera looking down +z.
Vec3f rayThrough(const test::TempDir& dir, int width, int height, double x, double y) {
    SceneDescription scene = parseSceneFile(
        dir.write("s.pbrt", "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\nWorldEnd\n"));
    CameraRay ray;
    EXPECT_TRUE(makeCamera(scene, {}, width, height, 0)->generateRay(x, y, 0.5f, 0.5f, ray));
    return ray.direction;
}

TEST(PerspectiveCamera, DefaultFovIs90DegreesAcrossTheShorterSide) {
    test::TempDir dir;
    const Vec3f side = rayThrough(dir, 8, 8, 0, 4);
    EXPECT_NEAR(std::fabs(side.x) / side.z, 1.0, 1e-6);  // tan 45 degrees
    EXPECT_NEAR(side.y, 0, 1e-6);
    const Vec3f top = rayThrough(dir, 16, 8, 8, 0);  // wide: the height is the shorter side
    EXPECT_NEAR(std::fabs(top.y) / top.z, 1.0, 1e-6);
    const Vec3f corner = rayThrough(dir, 16, 8, 0, 4);
    EXPECT_NEAR(std::fabs(corner.x) / corner.z, 2.0, 1e-6);
}

}  // namespace
}  // namespace lenslab
