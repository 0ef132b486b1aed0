#include "RadianceProbe.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace lenslab::test {

void writeImage(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    auto out = OIIO::ImageOutput::create(path);
    const bool eightBit = path.size() > 4 && path.substr(path.size() - 4) == ".png";
    OIIO::ImageSpec spec(width, height, 3, eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close())
        throw std::runtime_error("cannot write test image " + path);
}

}  // namespace lenslab::test
