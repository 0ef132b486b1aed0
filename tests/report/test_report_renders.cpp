// The report's renders of one tiny scene: shown at the scene's brightness (scaled by 4 N^2 / pi,
// the inverse of the image-side cone's pi / (4 N^2)), and cached under keys that name every
// setting of the render, the lens model included.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>

#include "BuildReport.h"
#include "PngCodec.h"
#include "ReportManifest.h"
#include "SiteFiles.h"

namespace fs = std::filesystem;
using namespace lenslab;

namespace {

constexpr double kSky = 0.2;  // the sky's radiance, linear

class ReportRenders : public ::testing::Test {
protected:
    // One build for the suite: dgauss.50mm (f/5.6, the report's render f-number) looking at a
    // uniform sky, focused at 100 m, where the film sees pi L / (4 N^2) at its centre.
    static void SetUpTestSuite() {
        options_.outputDir = fs::temp_directory_path() / ("lenslab-report-renders-" + std::to_string(getpid()));
        fs::remove_all(options_.outputDir);
        const fs::path scenes = options_.outputDir.string() + "-scenes";
        fs::create_directories(scenes);
        std::ofstream(scenes / "sky.pbrt")
            << "Film \"image\" \"integer xresolution\" 48 \"integer yresolution\" 32\n"
               "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"" LENSLAB_SOURCE_DIR
               "/lenses/dgauss.50mm.dat\" \"float focaldistance\" 100000\n"
               "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.2 0.2 0.2]\nWorldEnd\n";
        options_.sceneDir = scenes.string();
        options_.lenses = options_.renderLenses = {"dgauss.50mm"};
        options_.quick = true;
        summary_ = buildReport(options_);
        manifest_ = readManifest(options_.outputDir);
    }
    static void TearDownTestSuite() {
        fs::remove_all(options_.outputDir);
        fs::remove_all(options_.outputDir.string() + "-scenes");
    }
    static const ManifestItem& item(const std::string& id) {
        const auto it = manifest_.items.find(id);
        if (it == manifest_.items.end()) throw std::runtime_error("no manifest item " + id);
        return it->second;
    }

    static ReportOptions options_;
    static ReportSummary summary_;
    static ReportManifest manifest_;
};

ReportOptions ReportRenders::options_;
ReportSummary ReportRenders::summary_;
ReportManifest ReportRenders::manifest_;

double srgbToLinear(std::uint8_t byte) {
    const double s = byte / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

}  // namespace

TEST_F(ReportRenders, ShowTheSceneAtItsOwnBrightness) {
    ASSERT_TRUE(summary_.problems.empty()) << summary_.problems.front();
    for (const char* mode : {"exact", "thick"}) {
        SCOPED_TRACE(mode);
        const ManifestItem& render = item(std::string("render/sky/dgauss.50mm/") + mode);
        EXPECT_NEAR(render.data.at("exposure").get<double>(), 4 * 5.6 * 5.6 / M_PI, 1e-9);
        const RgbaImage png = decodePng(readBinaryFile(options_.outputDir / render.files.at(0)));
        const std::uint8_t* centre = &png.rgba[4 * (std::size_t(png.height / 2) * png.width + png.width / 2)];
        EXPECT_NEAR(srgbToLinear(centre[1]), kSky, 0.03 * kSky);
    }
}

TEST_F(ReportRenders, TheCacheKeyNamesTheLensModel) {
    const std::string exact = item("render/sky/dgauss.50mm/exact").hash, thick = item("render/sky/dgauss.50mm/thick").hash;
    EXPECT_NE(exact, thick);
    EXPECT_NE(item("speed/sky/dgauss.50mm/exact/1").hash, item("speed/sky/dgauss.50mm/thick/1").hash);
}

TEST_F(ReportRenders, KeepTheScenesAspect) {
    // The report's quick width of 96 pixels and the scene's 48 x 32 film: 64 rows.
    const ManifestItem& render = item("render/sky/dgauss.50mm/exact");
    EXPECT_EQ(render.data.at("width").get<int>(), 96);
    EXPECT_EQ(render.data.at("height").get<int>(), 64);
}
