// Image output: PNG (sRGB, 8 bit, through lenslab_image), OpenEXR (linear float RGB, tiled, the
// render's metadata as string attributes "lenslab.<key>") and a colour mosaic's raw DNG.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfStringAttribute.h>
#include <ImfTileDescription.h>
#include <ImfTiledOutputFile.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "film/DngFile.h"
#include "PngCodec.h"
#include "Render.h"

namespace lenslab {

namespace {

void checkImage(const Image& image) {
    if (image.width < 1 || image.height < 1 || image.rgb.size() != std::size_t(image.width) * image.height * 3)
        throw std::invalid_argument("image has no pixels or a wrong buffer size");
}

std::uint8_t toSrgb8(float linear) {
    if (!(linear > 0)) return 0;  // also NaN
    const float c = std::min(linear, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return std::uint8_t(std::lround(s * 255.0f));
}

// OpenEXR writes through this to memory.
class MemoryStream : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (pos_ + n > data_.size()) data_.resize(pos_ + n);
        std::memcpy(data_.data() + pos_, c, n);
        pos_ += n;
    }
    std::uint64_t tellp() override { return pos_; }
    void seekp(std::uint64_t pos) override { pos_ = pos; }
    std::vector<std::uint8_t> take() { return std::move(data_); }

private:
    std::vector<std::uint8_t> data_;
    std::uint64_t pos_ = 0;
};

}  // namespace

std::string imageFileExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::vector<std::uint8_t> encodePng(const Image& image, double exposure) {
    checkImage(image);
    if (!(exposure > 0) || !std::isfinite(exposure)) throw std::invalid_argument("exposure must be a positive number");
    std::vector<std::uint8_t> rgba(std::size_t(image.width) * image.height * 4);
    for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
        for (int c = 0; c < 3; ++c) rgba[4 * i + c] = toSrgb8(float(image.rgb[3 * i + c] * exposure));
        rgba[4 * i + 3] = 255;
    }
    return encodePngRgba8(image.width, image.height, rgba.data());
}

std::vector<std::uint8_t> encodeExr(const RenderOutput& output) {
    const Image& image = output.image;
    checkImage(image);
    Imf::Header header(image.width, image.height);
    header.setTileDescription(Imf::TileDescription(64, 64, Imf::ONE_LEVEL));
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    for (const auto& [key, value] : output.metadata) header.insert("lenslab." + key, Imf::StringAttribute(value));
    const RenderStats& s = output.stats;
    header.insert("lenslab.cameraRays", Imf::StringAttribute(std::to_string(s.cameraRays)));
    header.insert("lenslab.blockedCameraRays", Imf::StringAttribute(std::to_string(s.blockedCameraRays)));
    header.insert("lenslab.renderSeconds", Imf::StringAttribute(std::to_string(s.renderSeconds)));
    header.insert("lenslab.setupSeconds", Imf::StringAttribute(std::to_string(s.setupSeconds)));
    if (!output.warnings.empty()) {
        std::string lines;
        for (const std::string& w : output.warnings) lines += (lines.empty() ? "" : "\n") + w;
        header.insert("lenslab.renderWarnings", Imf::StringAttribute(lines));
    }

    Imf::FrameBuffer fb;
    const std::size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgb.data()));
    for (int c = 0; c < 3; ++c)
        fb.insert(c == 0 ? "R" : c == 1 ? "G" : "B", Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
    MemoryStream stream;
    {
        Imf::TiledOutputFile file(stream, header, 1);
        file.setFrameBuffer(fb);
        file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    }
    return stream.take();
}

void writeImageFile(const RenderOutput& output, const std::string& path, double exposure) {
    const std::string ext = imageFileExtension(path);
    std::vector<std::uint8_t> bytes;
    if (ext == ".png") bytes = encodePng(output.image, exposure);
    else if (ext == ".exr") bytes = encodeExr(output);
    else if (ext == ".dng") {
        if (!output.raw)
            throw std::invalid_argument("output '" + path + "': a raw DNG file needs a sensor with a colour mosaic (sensor key cfa)");
        bytes = encodeDng(*output.raw);
    } else throw std::invalid_argument("output '" + path + "': the extension must be .png, .exr or .dng");
    static std::atomic<unsigned> counter{0};
    const std::string temp = path + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot write '" + temp + "'");
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!out) {
            std::remove(temp.c_str());
            throw std::runtime_error("cannot write '" + temp + "'");
        }
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        throw std::runtime_error("cannot move the image to '" + path + "'");
    }
}

}  // namespace lenslab
