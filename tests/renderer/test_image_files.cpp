// EXR and PNG output: exact float round trip with metadata; sRGB encoding with exposure.
#include <gtest/gtest.h>

#include <ImfInputFile.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfStringAttribute.h>
#include <ImfTiledInputFile.h>

#include <fstream>
#include <random>

#include "PngCodec.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

RenderOutput randomOutput(int w, int h) {
    RenderOutput out;
    out.image.width = w;
    out.image.height = h;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 100.0f);
    for (int i = 0; i < w * h * 3; ++i) out.image.rgb.push_back(u(rng));
    out.metadata["lensName"] = "dgauss.50mm.dat";
    out.metadata["fstop"] = "2.8";
    return out;
}

TEST(ImageFiles, ExrRoundTripIsExactAndKeepsMetadata) {
    const RenderOutput out = randomOutput(131, 67);  // not a multiple of the 64-pixel tiles
    test::TempDir dir;
    const std::string path = dir.path() + "/round.exr";
    writeImageFile(out, path);

    Imf::TiledInputFile file(path.c_str());
    const Imf::Header& h = file.header();
    const auto dw = h.dataWindow();
    ASSERT_EQ(dw.max.x - dw.min.x + 1, 131);
    ASSERT_EQ(dw.max.y - dw.min.y + 1, 67);
    ASSERT_TRUE(h.hasTileDescription());
    const auto* lens = h.findTypedAttribute<Imf::StringAttribute>("lenslab.lensName");
    ASSERT_NE(lens, nullptr);
    EXPECT_EQ(lens->value(), "dgauss.50mm.dat");
    EXPECT_EQ(h.findTypedAttribute<Imf::StringAttribute>("lenslab.fstop")->value(), "2.8");
    EXPECT_EQ(h.channels().findChannel("R")->type, Imf::FLOAT);

    std::vector<float> back(out.image.rgb.size(), -1.0f);
    Imf::FrameBuffer fb;
    const std::size_t xs = 3 * sizeof(float), ys = xs * 131;
    for (int c = 0; c < 3; ++c)
        fb.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
                  Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(back.data()) + c * sizeof(float), xs, ys));
    file.setFrameBuffer(fb);
    file.readTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    EXPECT_EQ(back, out.image.rgb);
}

TEST(ImageFiles, PngIsSrgbWithExposure) {
    RenderOutput out;
    out.image = {3, 1, {0.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.5f, 4.0f, 0.2140411f, -1.0f}};
    test::TempDir dir;
    const std::string path = dir.path() + "/x.png";
    writeImageFile(out, path, 0.5);  // exposure halves: 0.25 -> sRGB 137, 2.0 -> clipped 255
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const RgbaImage img = decodePng(bytes);
    ASSERT_EQ(img.width, 3);
    EXPECT_EQ(img.rgba[0], 0);
    EXPECT_EQ(img.rgba[4], 137);
    EXPECT_EQ(img.rgba[8], 255);
    EXPECT_EQ(img.rgba[9], 92);   // 0.107 linear -> sRGB 0.361
    EXPECT_EQ(img.rgba[10], 0);   // negative clamps to black
}

TEST(ImageFiles, UnknownExtensionIsAnError) {
    RenderOutput out = randomOutput(2, 2);
    test::TempDir dir;
    EXPECT_THROW(writeImageFile(out, dir.path() + "/x.tiff"), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
