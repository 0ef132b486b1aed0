#include "film/DngFile.h"

#include <tiffio.h>
#include <tiffio.hxx>

#include <sstream>
#include <stdexcept>
#include <string>

#include "core/Spectrum.h"

namespace lenslab {

namespace {

constexpr std::uint16_t kD65 = 21;  // EXIF LightSource: D65, CalibrationIlluminant1's

// TIFFSetField's result checked: a tag libtiff refuses is a bug here, not the caller's.
template <typename... Values>
void setTag(TIFF* tif, std::uint32_t tag, Values... values) {
    if (TIFFSetField(tif, tag, values...) != 1) throw std::runtime_error("DNG: libtiff refused tag " + std::to_string(tag));
}

}  // namespace

std::vector<std::uint8_t> encodeDng(const RawMosaic& raw) {
    if (raw.width < 1 || raw.height < 1 || raw.dn.size() != std::size_t(raw.width) * std::size_t(raw.height))
        throw std::invalid_argument("DNG: the mosaic has no sites or a wrong buffer size");
    std::ostringstream stream;
    TIFF* tif = TIFFStreamOpen("raw.dng", static_cast<std::ostream*>(&stream));
    if (!tif) throw std::runtime_error("DNG: libtiff could not start the file");
    try {
        setTag(tif, TIFFTAG_SUBFILETYPE, std::uint32_t(0));  // the full-resolution raw image
        setTag(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(raw.width));
        setTag(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(raw.height));
        setTag(tif, TIFFTAG_BITSPERSAMPLE, std::uint16_t(16));
        setTag(tif, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(1));
        setTag(tif, TIFFTAG_COMPRESSION, std::uint16_t(COMPRESSION_NONE));
        setTag(tif, TIFFTAG_PHOTOMETRIC, std::uint16_t(PHOTOMETRIC_CFA));
        setTag(tif, TIFFTAG_PLANARCONFIG, std::uint16_t(PLANARCONFIG_CONTIG));
        setTag(tif, TIFFTAG_ORIENTATION, std::uint16_t(ORIENTATION_TOPLEFT));
        setTag(tif, TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(tif, 0));
        setTag(tif, TIFFTAG_MAKE, "lenslab");
        setTag(tif, TIFFTAG_MODEL, "simulated sensor");
        setTag(tif, TIFFTAG_SOFTWARE, "lenslab");
        setTag(tif, TIFFTAG_UNIQUECAMERAMODEL, "lenslab simulated sensor");
        if (!raw.description.empty()) setTag(tif, TIFFTAG_IMAGEDESCRIPTION, raw.description.c_str());
        const std::uint8_t version[4] = {1, 4, 0, 0}, backwardVersion[4] = {1, 1, 0, 0};
        setTag(tif, TIFFTAG_DNGVERSION, version);
        setTag(tif, TIFFTAG_DNGBACKWARDVERSION, backwardVersion);
        const std::uint16_t repeat[2] = {2, 2};
        setTag(tif, TIFFTAG_CFAREPEATPATTERNDIM, repeat);
        std::uint8_t cfa[4];  // CFAPattern's colours: 0 red, 1 green, 2 blue, as the channels
        for (std::size_t i = 0; i < 4; ++i) cfa[i] = std::uint8_t(raw.pattern.channels[i]);
        setTag(tif, TIFFTAG_CFAPATTERN, std::uint16_t(4), cfa);
        const float black = float(raw.blackLevelDn);
        setTag(tif, TIFFTAG_BLACKLEVEL, std::uint16_t(1), &black);
        const std::uint32_t white = std::uint32_t(raw.whiteLevelDn);
        setTag(tif, TIFFTAG_WHITELEVEL, std::uint16_t(1), &white);
        // XYZ to the camera's channels, linear Rec. 709: the columns are the images of X, Y and Z.
        const Vec3f x = xyzToRgb(1, 0, 0), y = xyzToRgb(0, 1, 0), z = xyzToRgb(0, 0, 1);
        const float colorMatrix[9] = {x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z};
        setTag(tif, TIFFTAG_COLORMATRIX1, std::uint16_t(9), colorMatrix);
        setTag(tif, TIFFTAG_CALIBRATIONILLUMINANT1, kD65);
        const float neutral[3] = {1, 1, 1};
        setTag(tif, TIFFTAG_ASSHOTNEUTRAL, std::uint16_t(3), neutral);
        std::vector<std::uint16_t> row(std::size_t(raw.width));
        for (int r = 0; r < raw.height; ++r) {
            const auto first = raw.dn.begin() + std::ptrdiff_t(r) * raw.width;
            row.assign(first, first + raw.width);
            if (TIFFWriteScanline(tif, row.data(), std::uint32_t(r), 0) != 1) throw std::runtime_error("DNG: libtiff could not write a row");
        }
    } catch (...) {
        TIFFClose(tif);
        throw;
    }
    TIFFClose(tif);
    const std::string bytes = stream.str();
    return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
}

}  // namespace lenslab
