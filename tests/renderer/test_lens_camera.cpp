// What a real lens does to the picture, measured on renders: a stopped-down lens draws like a
// pinhole of the same field of view; defocus blurs a point into the thick lens's circle of
// confusion; exposure falls off as cos^4 toward the corners; a fisheye bends straight lines.
#include <gtest/gtest.h>

#include <cmath>

#include "settings/LensAnalysis.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

std::string decimalText(double v) { return std::to_string(v); }

// A matte checkerboard wall 3 m ahead under a uniform sky (radiance = albedo everywhere).
std::string checkerWall(const std::string& camera) {
    return camera +
           "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"directlighting\" \"integer maxdepth\" 1\n"
           "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
           "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 96 \"float vscale\" 96 \"rgb tex1\" [0.9 0.9 0.9] "
           "\"rgb tex2\" [0.1 0.1 0.1]\nMaterial \"matte\" \"texture Kd\" \"c\"\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-3 -3 3  3 -3 3  3 3 3  -3 3 3] "
           "\"float uv\" [0 0 1 0 1 1 0 1]\nWorldEnd\n";
}

// Mean |a - b| / mean over the central half of two images, each normalised by its own mean there.
double centralDifference(const Image& a, const Image& b) {
    double ma = 0, mb = 0, diff = 0;
    int n = 0;
    for (int y = a.height / 4; y < 3 * a.height / 4; ++y)
        for (int x = a.width / 4; x < 3 * a.width / 4; ++x) {
            ma += test::lum(a, x, y);
            mb += test::lum(b, x, y);
            ++n;
        }
    ma /= n;
    mb /= n;
    for (int y = a.height / 4; y < 3 * a.height / 4; ++y)
        for (int x = a.width / 4; x < 3 * a.width / 4; ++x)
            diff += std::fabs(test::lum(a, x, y) / ma - test::lum(b, x, y) / mb);
    return diff / n;
}

TEST(LensCamera, TinyApertureMatchesPinholeOfSameFieldOfView) {
    test::TempDir dir;
    const double focus = 3000, diag = 30, fstop = 64;
    const LensAnalysis a = analyzeLens(loadLensSystem(test::lensPath("dgauss.dat")), fstop, focus);
    // Paraxially, a ray aimed at P' leaves from P at the same angle: the pinhole sits at the
    // entrance pupil (the centre of perspective) and sees half the film side at atan(h / (P' - film)).
    const double imageDistance = a.firstOrder.zPPrime - a.focus.imageZExact;
    const double fov = 2 * std::atan(0.5 * diag / std::sqrt(2.0) / imageDistance) * 180 / M_PI;
    const double pupilZm = a.pupils.entrance.z / 1000.0;
    const std::string realistic = dir.write("r.pbrt", checkerWall(
        test::courseCamera("dgauss.dat", "\"float fstop\" ") + decimalText(fstop) +
        " \"float focaldistance\" " + decimalText(focus) + " \"float filmdiagonal\" " + decimalText(diag) + " \"bool simpleweighting\" true"));
    const auto pinhole = [&](double fovDegrees) {
        return dir.write("p.pbrt", checkerWall("Translate 0 0 " + decimalText(-pupilZm) + "\nCamera \"perspective\" \"float fov\" " +
                                               decimalText(fovDegrees)));
    };
    const Image r = test::render(realistic, 96, 96, 32).image;
    const double same = centralDifference(r, test::render(pinhole(fov), 96, 96, 32).image);
    const double wider = centralDifference(r, test::render(pinhole(fov * 1.03), 96, 96, 32).image);
    RecordProperty("difference_same_fov", decimalText(same));
    EXPECT_LT(same, 0.08) << "fov " << fov;
    EXPECT_GT(wider, 2 * same) << "the comparison must notice a 3% change of field of view";
}

// A small glowing ball 1 m in front of a lens focused at 2 m: its image is a blur disc.
struct Blur {
    double radiusMm, predictedMm;
};

Blur measureBlur(const std::string& mode) {
    test::TempDir dir;
    const double fstop = 4, focus = 2000, object = 1000, diag = 35, ball = 2.0;  // mm
    const int res = 256;
    const std::string scene = dir.write("coc.pbrt",
        test::courseCamera("dgauss.dat", "\"float fstop\" ") + decimalText(fstop) +
        " \"float focaldistance\" " + decimalText(focus) + " \"float filmdiagonal\" " + decimalText(diag) + " \"string mode\" \"" + mode +
        "\"\nFilm \"image\"\nPixelFilter \"box\"\nWorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
        "Translate 0 0 " + decimalText(object / 1000) + "\nShape \"sphere\" \"float radius\" " + decimalText(ball / 1000) +
        "\nAttributeEnd\nWorldEnd\n");
    RenderSettings s;
    s.crop = std::array<double, 4>{0.4, 0.6, 0.4, 0.6};
    const Image im = test::render(scene, res, res, 256, s).image;
    const double pixelMm = diag / std::hypot(res, res);
    double sum = 0, sx = 0, sy = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double v = test::lum(im, x, y);
            sum += v;
            sx += v * x;
            sy += v * y;
        }
    const double cx = sx / sum, cy = sy / sum;
    double m2 = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            m2 += test::lum(im, x, y) * ((x - cx) * (x - cx) + (y - cy) * (y - cy));
    // Box pixels add their own spread (1/12 of a pixel squared per axis) to the measured moment.
    m2 = m2 / sum * pixelMm * pixelMm - pixelMm * pixelMm / 6;
    // Thick-lens prediction: the cone from the exit pupil converging on the ball's image, cut by the film.
    const LensAnalysis a = analyzeLens(loadLensSystem(test::lensPath("dgauss.dat")), fstop, focus);
    const double filmZ = mode == "exact" ? a.focus.imageZExact : a.focus.imageZThick;
    const double zeta = object - a.firstOrder.zP;  // object at z = +object (front vertex at 0)
    const double f = a.firstOrder.efl;
    const double imageZ = a.firstOrder.zPPrime - f * zeta / (zeta - f);
    const double coc = a.pupils.exit.diameter * std::fabs(filmZ - imageZ) / std::fabs(a.pupils.exit.z - imageZ);
    const double ballImage = ball * f / (zeta - f);
    // A uniform disc of radius R has a second moment R^2 / 2; the ball's own image adds its own.
    const double radius = std::sqrt(std::max(0.0, 2 * m2 - ballImage * ballImage));
    return {radius, 0.5 * coc};
}

TEST(LensCamera, DefocusBlurMatchesThickLensCircleOfConfusionApproximate) {
    const Blur b = measureBlur("thick");
    RecordProperty("blur_radius_mm", decimalText(b.radiusMm));
    RecordProperty("predicted_mm", decimalText(b.predictedMm));
    EXPECT_NEAR(b.radiusMm / b.predictedMm, 1.0, 0.05) << b.radiusMm << " vs " << b.predictedMm;
}

TEST(LensCamera, DefocusBlurMatchesThickLensCircleOfConfusionAccurate) {
    const Blur b = measureBlur("exact");
    RecordProperty("blur_radius_mm", decimalText(b.radiusMm));
    RecordProperty("predicted_mm", decimalText(b.predictedMm));
    EXPECT_NEAR(b.radiusMm / b.predictedMm, 1.0, 0.10) << b.radiusMm << " vs " << b.predictedMm;
}

// Irradiance across the film from a uniform emitting wall, against cos^4 of the angle from the
// (paraxial) exit pupil centre; returns the worst relative deviation along the diagonal.
void checkCosFourthFalloff(const std::string& mode, double tolerance) {
    test::TempDir dir;
    const double fstop = 16, focus = 2000, diag = 70;
    const int res = 96;
    const std::string scene = dir.write("wall.pbrt",
        test::courseCamera("dgauss.dat", "\"float fstop\" ") + decimalText(fstop) +
        " \"float focaldistance\" " + decimalText(focus) + " \"float filmdiagonal\" " + decimalText(diag) + " \"string mode\" \"" + mode +
        "\"\nFilm \"image\"\nPixelFilter \"box\"\nWorldBegin\nAttributeBegin\n"
        "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-20 -20 2  20 -20 2  20 20 2  -20 20 2]\n"
        "AttributeEnd\nWorldEnd\n");
    const Image im = test::render(scene, res, res, 64).image;
    const LensAnalysis a = analyzeLens(loadLensSystem(test::lensPath("dgauss.dat")), fstop, focus);
    const double filmZ = mode == "exact" ? a.focus.imageZExact : a.focus.imageZThick, xpZ = a.pupils.exit.z, xpR = 0.5 * a.pupils.exit.diameter;
    const double pixelMm = diag / std::hypot(res, res);
    // Average 2x2 pixels around points along the diagonal (where the falloff is largest).
    const auto measured = [&](int k) {
        double s = 0;
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) s += test::lum(im, k + dx, k + dy);
        return s / 4;
    };
    const auto cos4 = [&](int k) {
        const double r = std::hypot(k + 1 - res / 2.0, k + 1 - res / 2.0) * pixelMm;
        const double c = (xpZ - filmZ) / std::hypot(xpZ - filmZ, r);
        return c * c * c * c;
    };
    const int centre = res / 2 - 1;
    // On the axis: irradiance = L * pupil solid angle projected, pi sin^2(u).
    const double d = xpZ - filmZ;
    EXPECT_NEAR(measured(centre) / (M_PI * xpR * xpR / (xpR * xpR + d * d)), 1.0, 0.03);
    for (int k : {2, 12, 24}) {
        const double ratio = measured(k) / measured(centre);
        EXPECT_NEAR(ratio / cos4(k), 1.0, tolerance) << mode << ", pixel " << k << ": measured " << ratio << ", cos^4 " << cos4(k);
    }
    EXPECT_LT(measured(2) / measured(centre), 0.9);  // a visible falloff, not a flat field
}

// The thick lens's pupil is an exact disc: the small-pupil cos^4 law holds to a percent.
TEST(LensCamera, WhiteWallFallsOffAsCosFourthApproximate) { checkCosFourthFalloff("thick", 0.01); }

// The real double Gauss adds pupil aberration (its exit pupil looks larger off axis): within 5%.
TEST(LensCamera, WhiteWallFallsOffAsCosFourthAccurate) { checkCosFourthFalloff("exact", 0.05); }

// The row of a thin glowing horizontal bar above the axis, per column (intensity-weighted).
std::vector<double> barRows(const std::string& camera, int res) {
    test::TempDir dir;
    const std::string scene = dir.write("bar.pbrt", camera +
        "\nFilm \"image\"\nPixelFilter \"box\"\nWorldBegin\nAttributeBegin\n"
        "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-4 0.40 1  4 0.40 1  4 0.42 1  -4 0.42 1]\n"
        "AttributeEnd\nWorldEnd\n");
    const Image im = test::render(scene, res, res, 16).image;
    std::vector<double> rows;
    for (int x = 0; x < res; ++x) {
        double s = 0, sy = 0;
        for (int y = 0; y < res / 2; ++y) {
            s += test::lum(im, x, y);
            sy += test::lum(im, x, y) * y;
        }
        rows.push_back(s > 0 ? sy / s : -1);
    }
    return rows;
}

TEST(LensCamera, FisheyeBendsStraightLinesIntoBarrels) {
    const int res = 128;
    const std::vector<double> fisheye = barRows(
        test::courseCamera("fisheye.dat", "\"float fstop\" 8 \"float focaldistance\" 1000 ") +
        "\"float filmdiagonal\" 250", res);
    const std::vector<double> pinhole = barRows("Camera \"perspective\" \"float fov\" 70", res);
    const int edge = res / 16, middle = res / 2;
    ASSERT_GT(fisheye[edge], 0);
    ASSERT_GT(fisheye[middle], 0);
    // Barrel: magnification falls off-axis, so the bar's ends bend toward the image centre
    // (larger row numbers for a bar in the upper half) while the pinhole keeps it straight.
    const double bow = fisheye[edge] - fisheye[middle];
    const double bowRight = fisheye[res - 1 - edge] - fisheye[middle];
    RecordProperty("fisheye_bow_pixels", decimalText(bow));
    EXPECT_GT(bow, 4.0);
    EXPECT_GT(bowRight, 4.0);
    EXPECT_LT(std::fabs(pinhole[edge] - pinhole[middle]), 0.5);
}

}  // namespace
}  // namespace lenslab
