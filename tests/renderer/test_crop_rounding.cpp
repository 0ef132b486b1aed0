// A crop window whose edges fall inside pixels is rounded as pbrt-v3 rounds it: every edge up
// (ceil), so 0.25..0.75 of 10 pixels is pixels 3 to 7, five wide.
#include <gtest/gtest.h>

#include "TestScenes.h"

namespace lenslab {
namespace {

TEST(CropRounding, EdgesInsidePixelsRoundUp) {
    test::TempDir dir;
    const std::string scene = dir.write("s.pbrt", "Camera \"perspective\"\nWorldBegin\nWorldEnd\n");
    RenderSettings s;
    s.crop = std::array<double, 4>{0.25, 0.75, 0.15, 0.55};
    const RenderOutput out = test::render(scene, 10, 10, 1, s);
    EXPECT_EQ(out.metadata.at("cropPixels"), "3,8,2,6");  // ceil(2.5), ceil(7.5), ceil(1.5), ceil(5.5)
    EXPECT_EQ(out.image.width, 5);
    EXPECT_EQ(out.image.height, 4);
}

}  // namespace
}  // namespace lenslab
