#pragma once
// Helpers for renderer tests: scene files written to a fresh temporary folder, image measurements.
#include <string>

#include "Render.h"
#include "TempDir.h"

namespace lenslab::test {

std::string lensPath(const std::string& name);  // lenslab's bundled lens table

// A Camera "realistic" with the course's parameter names for a bundled lens (`params` follow the
// lens), preceded by the Scale that brings a world in metres into its millimetre camera space.
std::string courseCamera(const std::string& lens, const std::string& params);

// The message of the SceneError that parsing `path` throws, or "(no error)".
std::string sceneErrorOf(const std::string& path);

// Renders with the given settings (threads 2 unless set).
RenderOutput render(const std::string& scene, int width, int height, int spp, RenderSettings s = {});

inline float lum(const Image& im, int x, int y) {
    const float* p = &im.rgb[(std::size_t(y) * im.width + x) * 3];
    return (p[0] + p[1] + p[2]) / 3.0f;
}

// The mean of lum over the whole image.
inline double meanLum(const Image& im) {
    double sum = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) sum += lum(im, x, y);
    return sum / (double(im.width) * im.height);
}

}  // namespace lenslab::test
