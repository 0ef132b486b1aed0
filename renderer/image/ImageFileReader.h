#pragma once
// Image files of any format OpenImageIO reads (EXR, HDR, PFM, PNG, TGA, JPEG, TIFF, ...), decoded
// to floats. OpenImageIO drags in some 250 shared libraries (video codecs, OpenCV, GStreamer) that
// cost every lenslab process 0.4 s to load, so it lives in a plugin loaded on the first read:
// only scenes with image files pay for it, and none with EXR colour or luminance files, which
// OpenEXR reads (ExrFileReader.h), or 8-bit PNGs, which lenslab's codec reads (as RGBA).
#include <string>
#include <vector>

namespace lenslab {

struct DecodedImage {
    int width = 0, height = 0, channels = 0;
    bool floatingPoint = false;  // stored as floats (linear); otherwise integers (usually sRGB-encoded)
    bool eightBit = false;       // 8-bit integers: values are exact multiples of 1/255
    std::vector<float> pixels;   // row-major, top row first, `channels` floats per pixel; integers scaled to [0, 1]; colours not multiplied by alpha
};

// Throws std::runtime_error with OpenEXR's or OpenImageIO's reason when the file cannot be read.
DecodedImage readImageFile(const std::string& path);

}  // namespace lenslab
