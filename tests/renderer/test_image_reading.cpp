// Image files read without the OpenImageIO plugin. EXR files by OpenEXR: colour with alpha in R,
// G, B, A order over an offset data window, luminance, exact values; other channels left to the
// plugin, damaged files an error. 8-bit PNGs by lenslab's codec: exact multiples of 1/255, a
// header claiming too many pixels refused before anything is allocated.
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <half.h>

#include <fstream>
#include <stdexcept>

#include "ExrFileReader.h"
#include "PngCodec.h"
#include "TempDir.h"

namespace lenslab {
namespace {

// Writes channels `names` (each value: 100 * channel + pixel index, then / 8: exact in half) over
// the data window x0..x0+w-1, y0..y0+h-1.
void writeExrChannels(const std::string& path, const std::vector<std::string>& names, Imf::PixelType type, int x0, int y0, int w, int h) {
    Imf::Header header(Imath::Box2i({0, 0}, {x0 + w + 3, y0 + h + 3}), Imath::Box2i({x0, y0}, {x0 + w - 1, y0 + h - 1}));
    for (const std::string& n : names) header.channels().insert(n, Imf::Channel(type));
    std::vector<std::vector<float>> values(names.size());
    std::vector<std::vector<half>> halves(names.size());
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < names.size(); ++c) {
        for (int i = 0; i < w * h; ++i) values[c].push_back((100.0f * c + i) / 8);
        halves[c].assign(values[c].begin(), values[c].end());
        const bool isHalf = type == Imf::HALF;
        void* base = isHalf ? static_cast<void*>(halves[c].data()) : values[c].data();
        const std::size_t bytes = isHalf ? sizeof(half) : sizeof(float);
        frame.insert(names[c], Imf::Slice::Make(type, base, header.dataWindow(), bytes, bytes * w));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
}

TEST(ExrReading, ColourAndAlphaComeInRgbaOrderOverTheDataWindow) {
    test::TempDir dir;
    const std::string path = dir.path() + "/rgba.exr";
    writeExrChannels(path, {"B", "A", "R", "G"}, Imf::HALF, 5, 7, 4, 3);
    ASSERT_TRUE(isExrFile(path));
    const std::optional<DecodedImage> image = readExrFile(path);
    ASSERT_TRUE(image);
    EXPECT_EQ(image->width, 4);
    EXPECT_EQ(image->height, 3);
    ASSERT_EQ(image->channels, 4);
    EXPECT_TRUE(image->floatingPoint);
    // Written as B, A, R, G: channel indices 0..3 in that list.
    const int written[4] = {2, 3, 0, 1};
    for (int i = 0; i < 12; ++i)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(image->pixels[i * 4 + c], (100.0f * written[c] + i) / 8) << i << " " << c;
}

TEST(ExrReading, LuminanceIsOneChannel) {
    test::TempDir dir;
    const std::string path = dir.path() + "/y.exr";
    writeExrChannels(path, {"Y"}, Imf::FLOAT, 0, 0, 3, 2);
    const DecodedImage image = readImageFile(path);
    ASSERT_EQ(image.channels, 1);
    ASSERT_EQ(image.pixels.size(), 6u);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(image.pixels[i], i / 8.0f);
}

TEST(ExrReading, OtherChannelsGoToTheGeneralReader) {
    test::TempDir dir;
    const std::string path = dir.path() + "/z.exr";
    writeExrChannels(path, {"Z"}, Imf::FLOAT, 0, 0, 2, 2);
    EXPECT_FALSE(readExrFile(path));
    const DecodedImage image = readImageFile(path);  // OpenImageIO reads the depth channel
    ASSERT_EQ(image.channels, 1);
    EXPECT_EQ(image.pixels[3], 3 / 8.0f);
}

TEST(ExrReading, DamagedFilesAreErrors) {
    test::TempDir dir;
    const std::string path = dir.path() + "/rgb.exr";
    writeExrChannels(path, {"R", "G", "B"}, Imf::HALF, 0, 0, 64, 64);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir.path() + "/cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    EXPECT_THROW(readImageFile(dir.path() + "/cut.exr"), std::runtime_error);
    std::ofstream(dir.path() + "/header.exr", std::ios::binary) << bytes.substr(0, 40);
    EXPECT_THROW(readImageFile(dir.path() + "/header.exr"), std::runtime_error);
    EXPECT_FALSE(isExrFile(dir.path() + "/none.exr"));
}

std::string writePng(const std::string& path, int width, int height) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < width * height * 4; ++i) rgba.push_back(std::uint8_t(i * 37 % 256));
    const std::vector<std::uint8_t> png = encodePngRgba8(width, height, rgba.data());
    const std::string bytes(png.begin(), png.end());
    std::ofstream(path, std::ios::binary) << bytes;
    return bytes;
}

TEST(PngReading, EightBitPixelsComeBackAsExactFractions) {
    test::TempDir dir;
    writePng(dir.path() + "/p.png", 5, 3);
    const DecodedImage image = readImageFile(dir.path() + "/p.png");
    EXPECT_EQ(image.width, 5);
    EXPECT_EQ(image.height, 3);
    ASSERT_EQ(image.channels, 4);
    EXPECT_TRUE(image.eightBit);
    EXPECT_FALSE(image.floatingPoint);
    for (int i = 0; i < 60; ++i) EXPECT_EQ(image.pixels[i], float(i * 37 % 256) / 255.0f) << i;
}

TEST(PngReading, HugeOrDamagedFilesAreErrors) {
    test::TempDir dir;
    std::string bytes = writePng(dir.path() + "/p.png", 4, 4);
    bytes[16] = bytes[20] = 0x01;  // IHDR: 16.8 M x 16.8 M pixels
    std::ofstream(dir.path() + "/huge.png", std::ios::binary) << bytes;
    try {
        readImageFile(dir.path() + "/huge.png");
        ADD_FAILURE() << "read a 2^48-pixel image";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("268 Mpixels"), std::string::npos) << e.what();
    }
    const std::string good = writePng(dir.path() + "/p.png", 4, 4);
    std::ofstream(dir.path() + "/cut.png", std::ios::binary) << good.substr(0, good.size() - 20);
    EXPECT_THROW(readImageFile(dir.path() + "/cut.png"), std::runtime_error);
}

}  // namespace
}  // namespace lenslab
