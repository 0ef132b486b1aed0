// Tiles in parallel: the same image for any thread count and tile size, every tile reported once
// (serialised), and cancellation within about a tile.
#include <gtest/gtest.h>

#include <mutex>
#include <set>

#include "TestScenes.h"

namespace lenslab {
namespace {

std::string sharedWorld(const std::string& lens) {
    return std::string(LENSLAB_SOURCE_DIR) + "/scenes/shared-" + lens + ".pbrt";
}

// Settings for a render driven through renderScene's tile callback: 16-pixel tiles, two threads.
RenderSettings tiledOnTwoThreads(const std::string& scene, int width, int height, int spp) {
    RenderSettings s;
    s.scenePath = scene;
    s.width = width;
    s.height = height;
    s.spp = spp;
    s.tileSize = 16;
    s.threads = 2;
    return s;
}

TEST(RenderTiles, SameImageForAnyThreadCountAndTileSize) {
    RenderSettings a, b;
    a.threads = 1;
    a.tileSize = 7;
    b.threads = 2;
    b.tileSize = 16;
    const RenderOutput one = test::render(sharedWorld("dgauss"), 40, 30, 4, a);
    const RenderOutput two = test::render(sharedWorld("dgauss"), 40, 30, 4, b);
    EXPECT_EQ(one.image.rgb, two.image.rgb);
    RenderSettings c = b;
    c.seed = 99;
    EXPECT_NE(test::render(sharedWorld("dgauss"), 40, 30, 4, c).image.rgb, one.image.rgb);
    EXPECT_EQ(one.stats.cameraRays, 40u * 30u * 4u);
}

TEST(RenderTiles, EveryTileReportedOnceAndSerially) {
    const RenderSettings s = tiledOnTwoThreads(sharedWorld("wide"), 50, 40, 1);
    std::set<std::pair<int, int>> seen;
    int inside = 0, maxInside = 0, calls = 0;
    std::mutex m;
    const RenderOutput out = renderScene(s, [&](const TileUpdate& u, const Image& im) {
        {
            std::lock_guard<std::mutex> l(m);
            maxInside = std::max(maxInside, ++inside);
        }
        EXPECT_EQ(im.width, 50);
        seen.insert({u.x0, u.y0});
        ++calls;
        EXPECT_EQ(u.tilesTotal, 4 * 3);
        EXPECT_EQ(u.tilesDone, calls);
        std::lock_guard<std::mutex> l(m);
        --inside;
    });
    EXPECT_EQ(seen.size(), 12u);
    EXPECT_EQ(calls, 12);
    EXPECT_EQ(maxInside, 1);
    EXPECT_GT(out.stats.raysTraced, 0u);
}

TEST(RenderTiles, CropRendersOnlyTheWindow) {
    RenderSettings s;
    s.crop = std::array<double, 4>{0.25, 0.75, 0.5, 1.0};
    const RenderOutput full = test::render(sharedWorld("telephoto"), 40, 40, 2);
    const RenderOutput crop = test::render(sharedWorld("telephoto"), 40, 40, 2, s);
    ASSERT_EQ(crop.image.width, 20);
    ASSERT_EQ(crop.image.height, 20);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) EXPECT_EQ(test::lum(crop.image, x, y), test::lum(full.image, x + 10, y + 20));
}

TEST(RenderTiles, CancelStopsWithinATile) {
    const RenderSettings s = tiledOnTwoThreads(sharedWorld("fisheye"), 128, 128, 4);
    std::atomic<bool> cancel{false};
    int calls = 0;
    EXPECT_THROW(renderScene(s, [&](const TileUpdate&, const Image&) {
                     ++calls;
                     cancel = true;
                 }, &cancel),
                 RenderCancelled);
    EXPECT_LE(calls, 2);  // the tile that asked, and at most one finishing in parallel
}

TEST(RenderTiles, MetadataNamesTheLens) {
    const RenderOutput out = test::render(sharedWorld("dgauss"), 16, 16, 1);
    EXPECT_EQ(out.metadata.at("camera"), "realistic");
    EXPECT_EQ(out.metadata.at("fstop"), "4");
    EXPECT_EQ(out.metadata.at("mode"), "exact");
    EXPECT_EQ(out.metadata.at("focusDistanceMm"), "5500");
    EXPECT_LT(double(out.stats.blockedCameraRays) / out.stats.cameraRays, 0.05);
}

}  // namespace
}  // namespace lenslab
