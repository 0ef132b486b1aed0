// Camera samples through a real lens: a uniformly lit wall seen through a wide-open telephoto comes
// out without dark pixels. Each pixel's lens samples cover the pupil whatever film samples they go
// with, so where a quarter of the pupil is vignetted about a quarter of the samples are lost, never
// all of them (the Sobol' dimensions used before lost all 16 in 25 pixels of the top rows).
#include <gtest/gtest.h>

#include "TestScenes.h"

namespace lenslab {
namespace {

TEST(LensSampling, UniformWallThroughWideOpenTelephotoHasNoDarkPixel) {
    test::TempDir dir;
    // pbrt-v3's parameters: the stop opened to 40 mm (the lens's widest), focus 5 m from the film;
    // a matte wall of albedo 0.5 under a uniform sky has radiance 0.5 everywhere.
    const std::string scene = dir.write("wall.pbrt",
        "LookAt 0 0 0  0 0 1  0 1 0\n"
        "Camera \"realistic\" \"string lensfile\" \"" + test::lensPath("telephoto.250mm.dat") +
        "\" \"float aperturediameter\" 40 \"float focusdistance\" 5\n"
        "Film \"image\" \"float diagonal\" 35\nPixelFilter \"box\"\n"
        "Integrator \"directlighting\" \"integer maxdepth\" 1\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
        "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-20 -20 5  20 -20 5  20 20 5  -20 20 5]\n"
        "WorldEnd\n");
    // The top rows of a 400 x 400 frame, where the telephoto vignettes and the dark pixels were.
    RenderSettings s;
    s.crop = std::array<double, 4>{0, 1, 0, 0.06};
    const RenderOutput out = test::render(scene, 400, 400, 16, s);
    int checked = 0, dark = 0;
    for (int y = 1; y < 23; ++y)
        for (int x = 1; x < 399; ++x) {
            double around = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (dx || dy) around += test::lum(out.image, x + dx, y + dy);
            around /= 8;
            if (!(around > 0.02)) continue;  // outside the lens's image circle
            ++checked;
            if (test::lum(out.image, x, y) < 0.25 * around) {
                ++dark;
                ADD_FAILURE() << "pixel (" << x << ", " << y << "): " << test::lum(out.image, x, y) << " against " << around;
            }
        }
    EXPECT_EQ(dark, 0);
    EXPECT_GT(checked, 8000);  // the rows are lit: the test looked at them
}

}  // namespace
}  // namespace lenslab
