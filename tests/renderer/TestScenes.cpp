#include "TestScenes.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace lenslab::test {

TempDir::TempDir() {
    static std::atomic<int> counter{0};
    path_ = (fs::temp_directory_path() / ("lenslab-render-test-" + std::to_string(::getpid()) + "-" +
                                          std::to_string(counter++))).string();
    fs::remove_all(path_);
    fs::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& text) const {
    const fs::path p = fs::path(path_) / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
}

std::string lensPath(const std::string& name) { return std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name; }

RenderOutput render(const std::string& scene, int width, int height, int spp, RenderSettings s) {
    s.scenePath = scene;
    s.width = width;
    s.height = height;
    s.spp = spp;
    if (s.threads == 0) s.threads = 2;
    return renderScene(s);
}

}  // namespace lenslab::test
