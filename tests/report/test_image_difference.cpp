// The report's difference of two pictures against closed forms: the RMS runs over pixels and the
// three colour channels (alpha left out), and the difference image shades each pixel by its
// largest channel difference times the gain, dark on white.
#include <gtest/gtest.h>

#include <cmath>

#include "ImageDifference.h"

using namespace lenslab;

TEST(ImageDifference, RmsOverPixelsAndChannelsAndTheLargestChannelShades) {
    const RgbaImage a{2, 1, {10, 20, 30, 255, 100, 100, 100, 255}};
    const RgbaImage b{2, 1, {10, 20, 30, 0, 100, 112, 103, 255}};  // alpha differs too: ignored
    EXPECT_NEAR(rmsDifference(a, b), std::sqrt((12.0 * 12 + 3 * 3) / 6), 1e-12);
    const RgbaImage d = differenceImage(a, b, 4);
    EXPECT_EQ(d.rgba[0], 255);           // identical: white
    EXPECT_EQ(d.rgba[4], 255 - 12 * 4);  // the largest channel difference, 12, times 4
}
