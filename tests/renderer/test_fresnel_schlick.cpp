// Schlick's approximation, which the substrate material's glossy layer uses, against its closed
// form r0 + (1 - r0)(1 - cos)^5: the white-furnace and sampling tests hold for any Fresnel factor
// in [0, 1], so only the values themselves tell its exponent.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/Fresnel.h"

namespace lenslab {
namespace {

TEST(FresnelSchlick, IsR0PlusOneMinusR0TimesOneMinusCosToTheFifth) {
    const Vec3f r0{0.04f, 0.2f, 0.5f};
    for (const float c : {1.0f, 0.8f, 0.5f, 0.2f, 0.0f}) {
        const Vec3f f = fresnelSchlick(c, r0);
        const double m5 = std::pow(1.0 - c, 5);
        EXPECT_NEAR(f.x, 0.04 + 0.96 * m5, 1e-6) << c;
        EXPECT_NEAR(f.y, 0.2 + 0.8 * m5, 1e-6) << c;
        EXPECT_NEAR(f.z, 0.5 + 0.5 * m5, 1e-6) << c;
    }
}

}  // namespace
}  // namespace lenslab
