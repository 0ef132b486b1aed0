// The imagemap texture: images written here as EXR and PNG through OpenImageIO, read back at
// texel centres (exact), between them (bilinear), outside [0, 1] per wrap mode, with scale,
// invert and sRGB decoding as pbrt-v3 (and pbrt-v4 for invert) define them.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>

#include "TempDir.h"
#include "TextureTests.h"

namespace lenslab {
namespace {

using namespace test;

// Pixels row by row from the top, RGB.
void writeImage(const std::string& path, int w, int h, OIIO::TypeDesc format, const std::vector<float>& rgb) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, format)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
    out->close();
}

// A 2x2 float image: top row A B, bottom row C D. pbrt-v3 puts t = 0 at the bottom, so texel
// centres (s, t) = (0.25, 0.25) is C, (0.75, 0.25) D, (0.25, 0.75) A, (0.75, 0.75) B.
const Vec3f A{0.1f, 0.2f, 0.3f}, B{1.5f, 2.5f, 3.5f}, C{0.123456789f, 7.25f, -0.5f}, D{0.0625f, 1e-3f, 100};

std::string writeTextureExr(const TempDir& dir) {
    const std::string path = dir.path() + "/quad.exr";
    writeImage(path, 2, 2, OIIO::TypeDesc::FLOAT, {A.x, A.y, A.z, B.x, B.y, B.z, C.x, C.y, C.z, D.x, D.y, D.z});
    return path;
}

std::shared_ptr<const Texture> image(const std::string& path, std::vector<Param> more = {},
                                     TextureKind kind = TextureKind::Spectrum) {
    more.push_back(stringParam("filename", path));
    return texture("imagemap", std::move(more), kind);
}

TEST(ImageTexture, ExrTexelsComeBackExactlyWithTheBottomRowAtTZero) {
    TempDir dir;
    auto t = image(writeTextureExr(dir));
    expectRgb(t->evaluate(hitAt(0.25f, 0.25f)), C, 0);
    expectRgb(t->evaluate(hitAt(0.75f, 0.25f)), D, 0);
    expectRgb(t->evaluate(hitAt(0.25f, 0.75f)), A, 0);
    expectRgb(t->evaluate(hitAt(0.75f, 0.75f)), B, 0);
    expectRgb(t->evaluate(hitAt(0.5f, 0.5f)), 0.25f * (A + B + C + D), 1e-4f);  // bilinear between centres
    expectRgb(t->evaluate(hitAt(0.5f, 0.25f)), 0.5f * (C + D), 1e-5f);
}

// Every texel of a 5x3 image (texels are stored in 4x4 tiles: this crosses tile edges).
TEST(ImageTexture, EveryTexelOfAnOddSizedImage) {
    TempDir dir;
    const int w = 5, h = 3;
    std::vector<float> rgb;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) rgb.insert(rgb.end(), {float(x), float(y), 0.5f});
    const std::string path = dir.path() + "/odd.exr";
    writeImage(path, w, h, OIIO::TypeDesc::FLOAT, rgb);
    auto t = image(path);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)  // file row y is t = (h - 1 - y + 0.5) / h
            expectRgb(t->evaluate(hitAt((x + 0.5f) / w, (h - 1 - y + 0.5f) / h)), {float(x), float(y), 0.5f}, 1e-5f);
}

// 8-bit formats are decoded, float formats are not; PFM (stored bottom row first) comes out the
// same way up as the others.
TEST(ImageTexture, ReadsTheCommonFormats) {
    TempDir dir;
    const auto decode = [](float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); };
    const std::vector<float> pixels = {64 / 255.0f, 128 / 255.0f, 1, 1, 0, 0};  // 1x2: top pixel, bottom pixel
    for (const char* ext : {"tga", "bmp"}) {
        const std::string path = dir.path() + "/p." + ext;
        writeImage(path, 1, 2, OIIO::TypeDesc::UINT8, pixels);
        expectRgb(image(path)->evaluate(hitAt(0.5f, 0.75f)), {decode(64 / 255.0f), decode(128 / 255.0f), 1}, 1e-6f);
    }
    for (const char* ext : {"hdr", "tif"}) {
        const std::string path = dir.path() + "/p." + ext;
        writeImage(path, 1, 2, OIIO::TypeDesc::FLOAT, pixels);
        expectRgb(image(path)->evaluate(hitAt(0.5f, 0.25f)), {1, 0, 0}, 1e-6f);
        expectRgb(image(path)->evaluate(hitAt(0.5f, 0.75f)), {pixels[0], pixels[1], pixels[2]}, 0.01f);  // RGBE: 1%
    }
    // JPEG is lossy: a flat grey 8x8 image stays within a few levels.
    const std::string jpeg = dir.path() + "/grey.jpg";
    writeImage(jpeg, 8, 8, OIIO::TypeDesc::UINT8, std::vector<float>(8 * 8 * 3, 0.5f));
    EXPECT_NEAR(image(jpeg)->evaluate(hitAt(0.5f, 0.5f)).y, decode(0.5f), 0.01f);
    // PFM, written by hand: rows from the bottom, little-endian (negative scale).
    const std::string pfm = dir.path() + "/p.pfm";
    {
        std::FILE* f = std::fopen(pfm.c_str(), "wb");
        ASSERT_TRUE(f);
        std::fputs("PF\n1 2\n-1.0\n", f);
        const float rows[6] = {1, 0, 0, 0, 0.25f, 2};  // bottom: red; top: (0, 0.25, 2)
        std::fwrite(rows, sizeof rows, 1, f);
        std::fclose(f);
    }
    expectRgb(image(pfm)->evaluate(hitAt(0.5f, 0.25f)), {1, 0, 0}, 0);
    expectRgb(image(pfm)->evaluate(hitAt(0.5f, 0.75f)), {0, 0.25f, 2}, 0);
}

TEST(ImageTexture, WrapModesOutsideTheUnitSquare) {
    TempDir dir;
    const std::string path = writeTextureExr(dir);
    auto repeat = image(path);
    auto clamp = image(path, {stringParam("wrap", "clamp")});
    auto black = image(path, {stringParam("wrap", "black")});
    // Texel centres one column right of the image (s = 1.25) and one left (s = -0.25).
    expectRgb(repeat->evaluate(hitAt(1.25f, 0.25f)), C, 0);
    expectRgb(repeat->evaluate(hitAt(-0.25f, 0.75f)), B, 0);
    expectRgb(repeat->evaluate(hitAt(3.25f, -1.25f)), A, 0);
    expectRgb(clamp->evaluate(hitAt(1.25f, 0.25f)), D, 0);
    expectRgb(clamp->evaluate(hitAt(-7.0f, 9.0f)), A, 0);
    expectRgb(black->evaluate(hitAt(1.25f, 0.25f)), {0, 0, 0}, 0);
    expectRgb(black->evaluate(hitAt(0.25f, -0.25f)), {0, 0, 0}, 0);
    expectRgb(black->evaluate(hitAt(1.0f, 0.25f)), 0.5f * D, 1e-6f);  // half way to the black border
    EXPECT_THROW(image(path, {stringParam("wrap", "mirror")}), SceneError);
}

TEST(ImageTexture, ScaleThenInvert) {
    TempDir dir;
    const std::string path = writeTextureExr(dir);
    expectRgb(image(path, {floatParam("scale", 0.5)})->evaluate(hitAt(0.25f, 0.75f)), 0.5f * A, 0);
    // invert: max(0, 1 - scale value).
    expectRgb(image(path, {floatParam("scale", 0.5), boolParam("invert", true)})->evaluate(hitAt(0.25f, 0.25f)),
              {1 - 0.5f * C.x, 0, 1.25f}, 1e-6f);
}

TEST(ImageTexture, EightBitImagesAreSrgbDecodedUnlessGammaIsFalse) {
    TempDir dir;
    const std::string png = dir.path() + "/pair.png";
    writeImage(png, 2, 1, OIIO::TypeDesc::UINT8, {128 / 255.0f, 64 / 255.0f, 1, 0, 0, 0});
    const auto decode = [](float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); };
    const float r = 128 / 255.0f, g = 64 / 255.0f;
    expectRgb(image(png)->evaluate(hitAt(0.25f, 0.5f)), {decode(r), decode(g), 1}, 1e-6f);
    expectRgb(image(png, {boolParam("gamma", false)})->evaluate(hitAt(0.25f, 0.5f)), {r, g, 1}, 1e-6f);
    // A float imagemap: the luminance of the stored values, then decoded (pbrt-v3's order).
    const float y = 0.212671f * r + 0.715160f * g + 0.072169f;
    expectRgb(image(png, {}, TextureKind::Float)->evaluate(hitAt(0.25f, 0.5f)), {decode(y), decode(y), decode(y)}, 1e-6f);
    // "point" filtering takes the nearest texel: no blend with the black right texel.
    expectRgb(image(png, {stringParam("filter", "point")})->evaluate(hitAt(0.45f, 0.5f)), {decode(r), decode(g), 1}, 1e-6f);
    // Alpha is ignored, as in pbrt-v3: colours are not multiplied by it.
    const std::string rgba = dir.path() + "/clear.png";
    {
        auto out = OIIO::ImageOutput::create(rgba);
        ASSERT_TRUE(out->open(rgba, OIIO::ImageSpec(1, 1, 4, OIIO::TypeDesc::UINT8)));
        const float pixel[4] = {r, g, 1, 0};
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixel));
        out->close();
    }
    expectRgb(image(rgba)->evaluate(hitAt(0.5f, 0.5f)), {decode(r), decode(g), 1}, 1e-6f);
    // A float EXR is linear: no decoding by default.
    expectRgb(image(writeTextureExr(dir))->evaluate(hitAt(0.25f, 0.75f)), A, 0);
}

TEST(ImageTexture, MissingOrUnreadableImageNamesTheFile) {
    TempDir dir;
    try {
        image(dir.path() + "/nowhere.png");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("nowhere.png"), std::string::npos) << e.what();
    }
    const std::string junk = dir.write("junk.png", "not an image");
    try {
        image(junk);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("junk.png"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
