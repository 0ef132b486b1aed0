// The diagram's fit against its closed form: the scale is the smaller of width / z span and
// height / (2 yHalf) pixels per mm, the z span centred horizontally, the axis on a pixel centre.
#include <gtest/gtest.h>

#include "ViewFit.h"

using namespace lenslab;

TEST(ViewFit, TheTighterSideSetsTheScale) {
    const PictureBox box{10, 20, 410, 120};  // 400 x 100 pixels
    const ViewTransform tall = fitView(-80, 20, 25, box);  // y limits: 100 / 50 beats 400 / 100
    EXPECT_DOUBLE_EQ(tall.scale, 2);
    EXPECT_DOUBLE_EQ(tall.xAtZ0, 210 + 0.5 * (-80 + 20) * 2);
    EXPECT_DOUBLE_EQ(tall.yAtAxis, 70.5);
    const ViewTransform wide = fitView(-80, 20, 5, box);  // z limits: 400 / 100 beats 100 / 10
    EXPECT_DOUBLE_EQ(wide.scale, 4);
}
