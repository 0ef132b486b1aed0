#include <gtest/gtest.h>

#include "PngCodec.h"

namespace lenslab {
namespace {

TEST(PngCodec, RoundTripsEveryPixel) {
    const int w = 7, h = 5;
    std::vector<std::uint8_t> pixels(w * h * 4);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 37 + 11);
    const RgbaImage image = decodePng(encodePngRgba8(w, h, pixels.data()));
    EXPECT_EQ(image.width, w);
    EXPECT_EQ(image.height, h);
    EXPECT_EQ(image.rgba, pixels);
}

TEST(PngCodec, RefusesBadSizesAndData) {
    const std::uint8_t pixel[4] = {};
    EXPECT_THROW(encodePngRgba8(0, 1, pixel), PngError);
    EXPECT_THROW(decodePng({1, 2, 3}), PngError);
    std::vector<std::uint8_t> truncated = encodePngRgba8(1, 1, pixel);
    truncated.resize(truncated.size() / 2);
    EXPECT_THROW(decodePng(truncated), PngError);
}

}  // namespace
}  // namespace lenslab
