#pragma once
// Helpers for renderer tests: scene files written to a fresh temporary folder, image measurements.
#include <string>

#include "Render.h"

namespace lenslab::test {

// A new empty folder under the system temp dir, removed when the object dies.
class TempDir {
public:
    TempDir();
    ~TempDir();
    const std::string& path() const { return path_; }
    // Writes `text` to path()/name (creating folders) and returns the full path.
    std::string write(const std::string& name, const std::string& text) const;

private:
    std::string path_;
};

std::string lensPath(const std::string& name);  // lenslab's bundled lens table

// Renders with the given settings (threads 2 unless set).
RenderOutput render(const std::string& scene, int width, int height, int spp, RenderSettings s = {});

inline float lum(const Image& im, int x, int y) {
    const float* p = &im.rgb[(std::size_t(y) * im.width + x) * 3];
    return (p[0] + p[1] + p[2]) / 3.0f;
}

}  // namespace lenslab::test
