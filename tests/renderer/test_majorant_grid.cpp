// The walk of a ray through the cells of a majorant grid: the cells in order, segments that tile
// the ray's span exactly, each with its own cell's majorant.
#include <gtest/gtest.h>

#include <vector>

#include "media/MajorantGrid.h"

namespace lenslab {
namespace {

struct Segment {
    float t0, t1, majorant;
};

std::vector<Segment> walk(const MajorantGrid& g, Vec3f o, Vec3f d, float t0, float t1) {
    std::vector<Segment> s;
    walkMajorants(g, o, d, t0, t1, [&](float a, float b, float m) {
        s.push_back({a, b, m});
        return true;
    });
    return s;
}

// 4 x 2 x 1 cells numbered by their index.
MajorantGrid numbered() {
    MajorantGrid g{4, 2, 1, {}};
    for (int i = 0; i < 8; ++i) g.values.push_back(float(i));
    return g;
}

TEST(MajorantGrid, AxisRayCrossesEachCellOnce) {
    const auto s = walk(numbered(), {0, 0.75f, 0.5f}, {1, 0, 0}, 0.1f, 0.9f);
    ASSERT_EQ(s.size(), 4u);
    const float ends[] = {0.25f, 0.5f, 0.75f, 0.9f};
    for (int i = 0; i < 4; ++i) {
        EXPECT_FLOAT_EQ(s[i].t0, i == 0 ? 0.1f : ends[i - 1]);
        EXPECT_FLOAT_EQ(s[i].t1, ends[i]);
        EXPECT_EQ(s[i].majorant, float(4 + i));  // the upper row, y cell 1
    }
}

// From the corner (1, 0) towards (0, 1) in the xy plane: x falls through 4 cells, y rises through
// 2; the crossings at x = 0.75, 0.5, 0.25 and y = 0.5 meet at t = 0.5 (x = y = 0.5).
TEST(MajorantGrid, DiagonalRayVisitsCellsInOrderAndTilesItsSpan) {
    const auto s = walk(numbered(), {1, 0, 0.5f}, {-1, 1, 0}, 0, 1);
    std::vector<float> majorants;
    float covered = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (i > 0) {
            EXPECT_FLOAT_EQ(s[i].t0, s[i - 1].t1);
        }
        covered += s[i].t1 - s[i].t0;
        majorants.push_back(s[i].majorant);
    }
    EXPECT_FLOAT_EQ(covered, 1);
    EXPECT_EQ(majorants, (std::vector<float>{3, 2, 5, 4}));
}

TEST(MajorantGrid, StopsWhenTheVisitSaysSo) {
    int calls = 0;
    walkMajorants(numbered(), {0, 0.25f, 0.5f}, {1, 0, 0}, 0, 1, [&](float, float, float) { return ++calls < 2; });
    EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace lenslab
