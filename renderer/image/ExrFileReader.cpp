#include "ExrFileReader.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <fstream>
#include <stdexcept>
#include <vector>

namespace lenslab {

namespace {

constexpr long long kMaxPixels = 1LL << 28;  // as the OpenImageIO plugin

// The channels lenslab reads, in the order its image users expect; empty if the file has neither
// colour nor luminance of a floating-point type.
std::vector<const char*> channelsToRead(const Imf::ChannelList& list) {
    const auto floating = [&](const char* name) {
        const Imf::Channel* c = list.findChannel(name);
        return c && (c->type == Imf::HALF || c->type == Imf::FLOAT);
    };
    std::vector<const char*> names;
    if (floating("R") && floating("G") && floating("B"))
        names = {"R", "G", "B"};
    else if (floating("Y"))
        names = {"Y"};
    else
        return {};
    if (floating("A")) names.push_back("A");
    return names;
}

}  // namespace

bool isExrFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[4] = {0, 0, 0, 0};
    in.read(reinterpret_cast<char*>(magic), 4);
    return in && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

std::optional<DecodedImage> readExrFile(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        const std::vector<const char*> names = channelsToRead(file.header().channels());
        if (names.empty()) return std::nullopt;
        const Imath::Box2i dw = file.header().dataWindow();
        const long long width = (long long)dw.max.x - dw.min.x + 1, height = (long long)dw.max.y - dw.min.y + 1;
        if (width < 1 || height < 1 || width * height > kMaxPixels) throw std::runtime_error("no pixels, or more than 268 Mpixels");
        DecodedImage image;
        image.width = int(width);
        image.height = int(height);
        image.channels = int(names.size());
        image.floatingPoint = true;
        image.pixels.assign(std::size_t(width * height) * names.size(), 0.0f);
        const std::size_t pixelBytes = sizeof(float) * names.size();
        Imf::FrameBuffer frame;
        for (std::size_t c = 0; c < names.size(); ++c)
            frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, dw, pixelBytes, pixelBytes * width));
        file.setFrameBuffer(frame);
        file.readPixels(dw.min.y, dw.max.y);
        return image;
    } catch (const std::runtime_error&) {
        throw;
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("OpenEXR: ") + e.what());
    }
}

}  // namespace lenslab
