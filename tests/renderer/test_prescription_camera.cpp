// The realistic camera through real prescriptions: a reflex lens's central obscuration turns an
// out-of-focus highlight into a ring, as its pictures show and a plain lens's do not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "TestScenes.h"

namespace lenslab {
namespace {

// A small glowing sphere 20 m ahead, in the dark; the lens focused nearer sees it as a disc.
std::string highlight(const std::string& lens, double fstop, double focusMm, double filmDiagonal) {
    return test::courseCamera(lens, "\"float fstop\" " + std::to_string(fstop) + " \"float focaldistance\" " +
                                        std::to_string(focusMm) + " \"float filmdiagonal\" " + std::to_string(filmDiagonal)) +
           "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\"\nWorldBegin\n"
           "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [100 100 100]\nTranslate 0 0 20\n"
           "Shape \"sphere\" \"float radius\" 0.005\nAttributeEnd\nWorldEnd\n";
}

// The disc's radial profile about its centroid, in one-pixel rings: its outer radius (the last ring
// brighter than 5% of the brightest ring), and the mean luminance inside a quarter of that radius
// and between 0.6 and 0.9 of it.
struct DiscProfile {
    double radius = 0, centre = 0, rim = 0;
};

DiscProfile profile(const Image& im) {
    double sx = 0, sy = 0, sw = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double l = test::lum(im, x, y);
            sx += l * (x + 0.5);
            sy += l * (y + 0.5);
            sw += l;
        }
    const double cx = sx / sw, cy = sy / sw;
    const int rings = im.width;
    std::vector<double> sum(rings, 0), count(rings, 0);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const int ring = std::min(rings - 1, int(std::hypot(x + 0.5 - cx, y + 0.5 - cy)));
            sum[ring] += test::lum(im, x, y);
            count[ring] += 1;
        }
    double brightest = 0;
    for (int k = 0; k < rings; ++k) brightest = std::max(brightest, count[k] ? sum[k] / count[k] : 0);
    DiscProfile p;
    for (int k = 0; k < rings; ++k)
        if (count[k] && sum[k] / count[k] > 0.05 * brightest) p.radius = k + 1;
    double c = 0, r = 0, nc = 0, nr = 0;
    for (int k = 0; k < rings; ++k) {
        const double d = (k + 0.5) / p.radius;
        if (d < 0.25) c += sum[k], nc += count[k];
        if (d > 0.6 && d < 0.9) r += sum[k], nr += count[k];
    }
    p.centre = nc ? c / nc : 0;
    p.rim = nr ? r / nr : 0;
    return p;
}

}  // namespace

TEST(PrescriptionCamera, ReflexLensDrawsAnOutOfFocusHighlightAsARing) {
    test::TempDir dir;
    // Focused at 6.5 m, a point 20 m away blurs to a disc of about 5 mm on the film: the image of the
    // pupil, with the secondary mirror's shadow (OBSC 19 of 37.3 mm) as its dark middle.
    const RenderOutput reflex =
        test::render(dir.write("reflex.pbrt", highlight("us4666259-ex1-reflex-500mm.zmx", 6.8, 6500, 12)), 64, 64, 64);
    const DiscProfile ring = profile(reflex.image);
    EXPECT_GT(ring.radius, 12);
    EXPECT_LT(ring.radius, 32);
    EXPECT_LT(ring.centre, 0.05 * ring.rim) << "centre " << ring.centre << " rim " << ring.rim;
    // The same highlight through the course's double Gauss (no obscuration) is a filled disc.
    const RenderOutput plain = test::render(dir.write("plain.pbrt", highlight("dgauss.dat", 2.8, 1500, 8)), 64, 64, 64);
    const DiscProfile disc = profile(plain.image);
    EXPECT_GT(disc.radius, 8);
    EXPECT_GT(disc.centre, 0.5 * disc.rim) << "centre " << disc.centre << " rim " << disc.rim;
}

}  // namespace lenslab
