// The render agrees with the analysis (issue 28): edges of scenes/slanted-edge.pbrt rendered through
// a lens, each crop's e-SFR against the analysis's geometric MTF times the square pixel's, within
// 0.05 up to half the pixel Nyquist. Small crops at modest sample counts keep it to seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "SlantedEdgeComparison.h"
#include "TempDir.h"

namespace lenslab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 0.05;

const std::string kScene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/slanted-edge.pbrt";

double sinc(double x) { return x == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }

EdgeCase edgeCase(const std::string& lens, double fstop, int step, MtfDirection direction) {
    EdgeCase c;
    c.scenePath = kScene;
    c.lensPath = lens;
    c.fstop = fstop;
    c.chartStep = step;
    c.direction = direction;
    c.cropPixels = 48;
    c.spp = 64;
    return c;
}

// Frequencies up to half the pixel Nyquist: a quarter cycle per pixel.
bool withinHalfNyquist(const EdgeComparison& e, std::size_t k) { return e.frequencies[k] * e.pixelMm <= 0.25 + 1e-12; }

// A plano-convex singlet, flat side to the scene (the stop on it), whose rear surface is the
// Cartesian oval of refraction from glass into air: the hyperboloid of conic -n^2 with its far focus
// in air. Light from a distant axial point meets it parallel and converges without aberration.
std::string cartesianSinglet(const test::TempDir& dir, double n, double focalLength) {
    const double radius = -(n - 1) * focalLength;  // centre toward the scene
    return dir.write("cartesian-singlet.zmx",
                     "VERS 140124\nMODE SEQ\nUNIT MM\n"
                     "SURF 0\n  CURV 0\n  DISZ INFINITY\n"
                     "SURF 1\n  STOP\n  CURV 0\n  DISZ 5\n  GLAS ___BLANK 1 0 " + std::to_string(n) + " 0\n  DIAM 10\n"
                     "SURF 2\n  CURV " + std::to_string(1 / radius) + "\n  CONI " + std::to_string(-n * n) +
                         "\n  DISZ " + std::to_string(focalLength) + "\n  DIAM 10\n"
                     "SURF 3\n  CURV 0\n  DISZ 0\n");
}

TEST(SlantedEdge, DiffractionLimitedSingletMeasuresThePixelAlone) {
    test::TempDir dir;
    // At f/8 the spherical aberration of the chart's finite 5 m (the oval is perfect for infinity) stays
    // below a micron.
    const EdgeComparison e = compareSlantedEdge(edgeCase(cartesianSinglet(dir, 1.5, 50), 8, 0, MtfDirection::Tangential));
    EXPECT_NEAR(std::abs(e.edge.angleDegrees), 5, 0.2);
    for (std::size_t k = 0; k < e.frequencies.size(); ++k) {
        if (!withinHalfNyquist(e, k)) continue;
        // The analysis sees no aberration at the chart's 5 m either...
        EXPECT_GT(e.lens[k], 0.99) << e.frequencies[k] << " lp/mm";
        // ... and the picture holds the square pixel's MTF along the edge's normal, nothing else.
        const double f = e.frequencies[k] * e.pixelMm;
        EXPECT_NEAR(e.measured[k], sinc(f * e.edge.normalX) * sinc(f * e.edge.normalY), kTolerance) << e.frequencies[k] << " lp/mm";
    }
}

// dgauss.50mm at f/4: on the axis, and at 16 degrees (0.7 of the 23 degrees of a 24 x 36 mm film's
// corner) across and along the radius, where coma and astigmatism part the two.
TEST(SlantedEdge, DoubleGaussOnTheAxisAndAtSevenTenthsOfTheField) {
    const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat";
    for (const auto& [step, direction] : {std::pair{0, MtfDirection::Tangential}, std::pair{8, MtfDirection::Tangential},
                                          std::pair{8, MtfDirection::Sagittal}}) {
        const EdgeComparison e = compareSlantedEdge(edgeCase(lens, 4, step, direction));
        SCOPED_TRACE(std::to_string(e.fieldDegrees) + " deg " + (direction == MtfDirection::Sagittal ? "sagittal" : "tangential"));
        EXPECT_NEAR(e.fieldDegrees, 2 * step, 0.1);
        double lensShare = 0;  // how far the lens moves the prediction from the pixel's MTF alone
        for (std::size_t k = 0; k < e.frequencies.size(); ++k) {
            if (!withinHalfNyquist(e, k)) continue;
            EXPECT_NEAR(e.measured[k], e.predicted[k], kTolerance) << e.frequencies[k] << " lp/mm";
            lensShare = std::max(lensShare, e.pixel[k] - e.predicted[k]);
        }
        // Off the axis the lens's own share is far larger than the tolerance: the check sees the lens.
        if (step > 0) {
            EXPECT_GT(lensShare, 4 * kTolerance);
        }
    }
}

// dgauss.50mm images the 20 degree edge 18.2 mm off the axis, past the 18 mm half height of the film.
TEST(SlantedEdge, AnEdgeImagedOffTheFilmIsRefused) {
    EXPECT_THROW(compareSlantedEdge(edgeCase(std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat", 4, 10, MtfDirection::Tangential)),
                 std::out_of_range);
}

}  // namespace
}  // namespace lenslab
