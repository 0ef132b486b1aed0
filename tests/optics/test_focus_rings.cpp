// The focus solve weighs the pupil by area. For third-order spherical aberration a ray at pupil
// height rho crosses the axis A rho^2 past F', and the least-RMS spot over a uniformly lit pupil
// lies two thirds of the marginal ray's A R^2 past F' (rays spread evenly in rho, not in area,
// would put it at three fifths). A slow singlet has nearly pure third-order aberration.
#include <gtest/gtest.h>

#include <limits>

#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Focus.h"
#include "prescription/LensTable.h"
#include "firstorder/Pupils.h"

using namespace lenslab;

namespace {

// A stop 2 mm in front of an equi-convex singlet (n 1.5, radii 50 mm, 4 mm thick): about f/8.
const char* kSinglet = "0 0 0 6\n50 2 1.5 20\n-50 4 0 20\n";

// Where the ray parallel to the axis at height h crosses the axis behind the lens.
double axisCrossingAt(const LensSystem& lens, double h) {
    const Ray in{{0, h, lens.frontZ() + 1}, {0, 0, -1}};
    const TraceResult t = traceRay(lens, in, TraceDirection::SceneToFilm);
    EXPECT_TRUE(t.ok());
    return t.ray.origin.z - t.ray.origin.y * t.ray.direction.z / t.ray.direction.y;
}

}  // namespace

TEST(FocusRings, BestFocusLiesTwoThirdsOfTheMarginalAberrationPastFPrime) {
    const LensSystem lens = buildLensSystem(parseLensTable(kSinglet, "singlet"));
    const FirstOrder fo = computeFirstOrder(lens);
    const Pupils pupils = computePupils(lens);
    const FocusResult f = focusAt(lens, fo, pupils, std::numeric_limits<double>::infinity());
    const double marginal = axisCrossingAt(lens, 0.5 * pupils.entrance.diameter) - fo.zFPrime;
    ASSERT_GT(marginal, 0.05);  // undercorrected: the marginal ray crosses nearer the lens (+z) than F'
    EXPECT_NEAR((f.imageZExact - fo.zFPrime) / marginal, 2.0 / 3, 0.01);
}
