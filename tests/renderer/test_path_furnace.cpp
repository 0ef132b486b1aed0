// The path integrator inside a glowing sphere (emission Le inward, matte albedo rho): light that
// bounced k times arrives as rho^k Le, so at maxdepth d the radiance is Le (1 - rho^(d+1)) / (1 - rho).
// Depth 1 tells pbrt-v3's path length from one bounce more; depth 8 needs Russian roulette
// (from the fourth bounce) to keep the long paths' weight.
#include <gtest/gtest.h>

#include <cmath>

#include "RadianceProbe.h"
#include "TempDir.h"

namespace lenslab {
namespace {

constexpr double kRho = 0.5;

TEST(PathFurnace, BouncesUpToMaxdepthEachAddRhoToTheKTimesLe) {
    test::TempDir dir;
    const std::string s = dir.write("s.pbrt", std::string(test::kProbeHeader) +
        "WorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\nReverseOrientation\nShape \"sphere\" \"float radius\" 10\n"
        "AttributeEnd\nWorldEnd\n");
    for (const int depth : {1, 8}) {
        const double expected = (1 - std::pow(kRho, depth + 1)) / (1 - kRho);
        const test::RadianceProbe probe(s, IntegratorType::Path, depth);
        EXPECT_NEAR(probe.mean({0, 0, 0}, {0.3f, 0.2f, 1}, 40000), expected, 0.004 * expected) << "maxdepth " << depth;
    }
}

}  // namespace
}  // namespace lenslab
