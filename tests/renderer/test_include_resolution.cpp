// Include names files relative to the MAIN scene file's folder, as pbrt-v3 does, even from an
// included file in another folder: a nested Include reaches parts/ from the top, not parts/parts/.
#include <gtest/gtest.h>

#include "scene/SceneDescription.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

TEST(IncludeResolution, NestedIncludesResolveFromTheMainScenesFolder) {
    test::TempDir dir;
    dir.write("parts/world.pbrt", "Include \"parts/ball.pbrt\"\n");
    dir.write("parts/ball.pbrt", "Shape \"sphere\" \"float radius\" 2\n");
    // A decoy where the including file's folder would lead: a different shape.
    dir.write("parts/parts/ball.pbrt", "Shape \"disk\" \"float radius\" 3\n");
    const std::string main = dir.write("main.pbrt", "Camera \"perspective\"\nWorldBegin\nInclude \"parts/world.pbrt\"\nWorldEnd\n");
    const SceneDescription scene = parseSceneFile(main);
    ASSERT_EQ(scene.shapes.size(), 1u);
    // The sphere of radius 2: its sample at (u, v) = (0.5, 0) lies on its equator, at x = 2.
    EXPECT_NEAR(scene.shapes[0].shape->samplePrimitive(0, 0.5f, 0).p.x, 2, 1e-6);
}

}  // namespace
}  // namespace lenslab
