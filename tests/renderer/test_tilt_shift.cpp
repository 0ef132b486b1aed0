// A tilt-shift lens (cameras/LensMount.h): the plane of focus of a tilted or swung lens lies where
// Scheimpflug's rule and the hinge rule put it, computed here from the lens's first-order points
// alone; a shifted lens moves its axis across the film; the film's irradiance through a tilted lens
// equals a brute-force integral of cos dw over the directions that pass the exact lens.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <regex>
#include <tuple>

#include "cameras/RealisticCamera.h"
#include "PassingSolidAngle.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

constexpr double kDeg = M_PI / 180;

struct P2 {
    double a = 0, b = 0;  // the two coordinates of the plane the lens turns in (x, z) or (y, z)
};

// The plane of focus of a lens turned by `turn` radians in the (a, z) plane about its rear principal
// point, by the hinge rule and Scheimpflug's rule (Merklinger; for a thick lens with the principal
// planes for the thin lens's plane): a line in that plane, returned as a point and a direction.
// A positive turn moves the lens's axis toward +a (a swing's +x; a tilt's -y when a = -y). The film
// is the paraxial one for the focus asked (where the rules' lens focuses; the exact lens puts its
// film at its own best focus for the same plane, a fraction of a millimetre away).
struct Line2 {
    P2 point, direction;
};
Line2 scheimpflugPlaneOfFocus(const FirstOrder& fo, double filmZ, double turn) {
    const P2 axis{std::sin(turn), std::cos(turn)};
    const P2 pivot{0, fo.zPPrime};
    const auto along = [&](double lensZ) { return P2{pivot.a + (lensZ - fo.zPPrime) * axis.a, pivot.b + (lensZ - fo.zPPrime) * axis.b}; };
    const P2 p = along(fo.zP), f = along(fo.zF);
    // Scheimpflug: the film (z = filmZ) meets the rear principal plane ((X - P') . axis = 0) at
    // a = (zP' - filmZ) / tan(turn); the front principal plane holds its conjugate, moved along the axis.
    const P2 sRear{(fo.zPPrime - filmZ) / std::tan(turn), filmZ};
    const P2 s{sRear.a + p.a - pivot.a, sRear.b + p.b - pivot.b};
    // Hinge: the front focal plane ((X - F) . axis = 0) meets the plane through P parallel to the film (z = P.z).
    const P2 h{f.a - (p.b - f.b) / std::tan(turn), p.b};
    const double len = std::hypot(h.a - s.a, h.b - s.b);
    return {s, {(h.a - s.a) / len, (h.b - s.b) / len}};
}

// Where a bundle of rays heading along +z converges: the point (x, y, z) that minimises the squared
// distances across z of the rays' lines, x - (ox + sx (z - oz)) and likewise in y, with their slopes
// s = d / dz (camera rays carry float directions: 1 - dz^2 would lose the small angles between them).
Vec3 convergence(const std::vector<CameraRay>& rays) {
    // Unknowns (x, y, z); each ray gives x - sx z = ox - sx oz and y - sy z = oy - sy oz.
    double a[3][3] = {}, b[3] = {};
    const auto add = [&](const double row[3], double rhs) {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) a[i][j] += row[i] * row[j];
            b[i] += row[i] * rhs;
        }
    };
    for (const CameraRay& r : rays) {
        const double sx = double(r.direction.x) / r.direction.z, sy = double(r.direction.y) / r.direction.z;
        const double rowX[3] = {1, 0, -sx}, rowY[3] = {0, 1, -sy};
        add(rowX, r.origin.x - sx * r.origin.z);
        add(rowY, r.origin.y - sy * r.origin.z);
    }
    // Cramer's rule for the 3 x 3 normal equations.
    const auto det = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    double x[3];
    for (int k = 0; k < 3; ++k) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
        x[k] = det(m) / d;
    }
    return {x[0], x[1], x[2]};
}

// The passing rays from raster point (rx, ry) over an n x n grid of lens samples.
std::vector<CameraRay> bundle(const RealisticCamera& camera, double rx, double ry, int n = 12) {
    std::vector<CameraRay> rays;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            CameraRay r;
            if (camera.generateRay(rx, ry, float((i + 0.5) / n), float((j + 0.5) / n), r)) rays.push_back(r);
        }
    return rays;
}

RealisticParams dgauss(double focusMm) {
    RealisticParams p = realisticParams(test::lensPath("dgauss.50mm.dat"), std::nullopt, focusMm);
    p.cameraUnitMm = 1;  // camera space in millimetres, its origin at the front vertex
    return p;
}

// The bundles from a column (tilt) or row (swing) of film points, through a lens turned by
// `degrees` and focused at 1 m: the angle of the line through their convergence points (degrees,
// in the plane of the turn, from the a axis), and the largest distance of the points from the
// predicted plane of focus over their distance.
struct PlaneOfFocusFit {
    double measured = 0, predicted = 0;  // degrees
    double worstOffset = 0;
};
PlaneOfFocusFit fitPlaneOfFocus(LensMode mode, double fstop, double degrees, bool swing, int from, int to) {
    RealisticParams p = dgauss(1000);
    p.mode = mode;
    p.settings.fstop = Setting{fstop, "test"};
    (swing ? p.mount.swingDegrees : p.mount.tiltDegrees) = degrees;
    const int width = 360, height = 240;
    const RealisticCamera camera(p, Transform{}, width, height, 0.5);
    const LensAnalysis& a = camera.analysis();
    // A tilt turns the axis toward -y, a swing toward +x: a = -y or x. Square to the axis (no turn)
    // the plane of focus is the plane z = const.
    const Line2 predicted = degrees != 0 ? scheimpflugPlaneOfFocus(a.firstOrder, a.focus.imageZThick, degrees * kDeg)
                                         : Line2{{0, 0}, {1, 0}};
    PlaneOfFocusFit fit;
    std::vector<P2> focused;
    for (int k = from; k <= to; k += 20) {
        const Vec3 c = convergence(swing ? bundle(camera, k * width / double(height), height / 2.0) : bundle(camera, width / 2.0, k));
        EXPECT_NEAR(swing ? c.y : c.x, 0, 1e-3 * std::fabs(c.z)) << "the plane of focus holds the turn's axis";
        const P2 q{swing ? c.x : -c.y, c.z};
        focused.push_back(q);
        const double off = (q.b - predicted.point.b) * predicted.direction.a - (q.a - predicted.point.a) * predicted.direction.b;
        fit.worstOffset = std::max(fit.worstOffset, std::fabs(off) / q.b);
    }
    // Angles of lines, taken in (-90, 90].
    const auto lineAngle = [](double da, double db) { return std::remainder(std::atan2(db, da), M_PI) / kDeg; };
    fit.measured = lineAngle(focused.back().a - focused.front().a, focused.back().b - focused.front().b);
    fit.predicted = lineAngle(predicted.direction.a, predicted.direction.b);
    return fit;
}

TEST(TiltShift, HingeRuleOfThePredictionIsFOverSinTilt) {
    // The helper's plane meets the plane through P parallel to the film f / sin(4 deg) from P (722 mm).
    const LensAnalysis a = analyzeLens(loadLensSystem(test::lensPath("dgauss.50mm.dat")), std::nullopt, 1000);
    const double t = 4 * kDeg;
    const Line2 predicted = scheimpflugPlaneOfFocus(a.firstOrder, a.focus.imageZThick, t);
    const double pA = (a.firstOrder.zP - a.firstOrder.zPPrime) * std::sin(t);
    const double pZ = a.firstOrder.zPPrime + (a.firstOrder.zP - a.firstOrder.zPPrime) * std::cos(t);
    const double toHinge = (pZ - predicted.point.b) / predicted.direction.b;
    EXPECT_NEAR(predicted.point.a + toHinge * predicted.direction.a - pA, a.firstOrder.efl / std::sin(t), 1e-9 * 722);
}

TEST(TiltShift, ThickLensFocusesOnTheScheimpflugPlaneExactly) {
    // The thick lens images planes onto planes (a collinear map), so a turned one focuses on the
    // predicted plane itself: tilted 4 degrees down, swung 3 degrees right.
    for (const bool swing : {false, true}) {
        const PlaneOfFocusFit fit = fitPlaneOfFocus(LensMode::Thick, 2.02, swing ? 3 : 4, swing, 20, 220);
        EXPECT_LT(fit.worstOffset, 1e-6) << (swing ? "swing" : "tilt");
        EXPECT_NEAR(fit.measured, fit.predicted, 1e-4) << (swing ? "swing" : "tilt");
    }
}

TEST(TiltShift, ExactLensFocusesNearTheScheimpflugPlane) {
    // The real lens at f/8, film points within 6 mm of the centre. Its field curvature, which a
    // camera sees magnified some 400 times in depth at 1 m, bends the plane of focus already square
    // to the axis (7 mm nearer at 93 mm off the axis than on it); tilted, the film's part of the
    // field moves off the lens's axis and the bend turns the fitted line by about 2 degrees (the
    // bundles' least-squares foci mix the sagittal and tangential ones; the render below, which sees
    // the sagittal focus, meets the rules within a degree). A wrong sign or pivot is off by tens.
    for (const bool swing : {false, true}) {
        const PlaneOfFocusFit square = fitPlaneOfFocus(LensMode::Exact, 8, 0, swing, 60, 180);
        EXPECT_NEAR(square.measured, 0, 0.1) << "square to the axis, a plane across it";
        const PlaneOfFocusFit turned = fitPlaneOfFocus(LensMode::Exact, 8, swing ? 3 : 4, swing, 60, 180);
        EXPECT_NEAR(turned.measured, turned.predicted, 2.5) << (swing ? "swing" : "tilt");
        EXPECT_LT(turned.worstOffset, 0.02) << (swing ? "swing" : "tilt");
    }
}

TEST(TiltShift, ShiftMovesTheAxisAcrossTheFilm) {
    // Focused at infinity with the lens shifted 6 mm right and 4 mm up, the film centre sees the
    // direction that a film point 6 mm left and 4 mm down of the axis sees: tan = shift / (P' - film).
    RealisticParams p = dgauss(std::numeric_limits<double>::infinity());
    p.settings.fstop = Setting{8, "test"};
    p.mount.shiftMm = {6, 4};
    const RealisticCamera camera(p, Transform{}, 300, 200, 0.5);
    const std::vector<CameraRay> rays = bundle(camera, 150, 100);
    ASSERT_GT(rays.size(), 50u);
    double dx = 0, dy = 0, dz = 0;
    for (const CameraRay& r : rays) {
        dx += r.direction.x;
        dy += r.direction.y;
        dz += r.direction.z;
    }
    const double back = camera.analysis().firstOrder.zPPrime - camera.filmZ();
    EXPECT_NEAR(dx / dz, 6 / back, 0.01 * 6 / back);
    EXPECT_NEAR(dy / dz, 4 / back, 0.01 * 4 / back);
    // And the film point under the lens's axis sees along the body's axis, every ray of its bundle
    // parallel (focus at infinity).
    double rx, ry;
    camera.rasterPoint(6, 4, rx, ry);
    for (const CameraRay& r : bundle(camera, rx, ry)) {
        EXPECT_NEAR(r.direction.x / r.direction.z, 0, 5e-4);
        EXPECT_NEAR(r.direction.y / r.direction.z, 0, 5e-4);
    }
}

TEST(TiltShift, TiltedFilmIrradianceEqualsTheProjectedSolidAngleThatPasses) {
    // E / L = integral of cos(film) dw over the directions that pass the lens: the camera's mean
    // weight over its lens samples, against cosine-weighted directions traced through the exact
    // lens from the same film point (found here from the tilt about P' by hand). Seen equal to 0.015%;
    // weighted by cos(aim)^2 instead of cos(film) cos(aim), the camera is 1-1.5% short.
    RealisticParams p = dgauss(2000);
    p.mount.tiltDegrees = 10;
    p.mount.swingDegrees = -4;
    p.exposureTime = 1;
    const int width = 240, height = 160;
    const RealisticCamera camera(p, Transform{}, width, height, 0.5);
    const LensAnalysis& a = camera.analysis();
    const double t = 10 * kDeg, s = -4 * kDeg;
    // R = Ry(s) Rx(t); lens space from body: p_L = P' + R^T (p_B - P').
    const double r[9] = {std::cos(s), std::sin(s) * std::sin(t), std::sin(s) * std::cos(t), 0, std::cos(t), -std::sin(t),
                         -std::sin(s), std::cos(s) * std::sin(t), std::cos(s) * std::cos(t)};
    const auto toLens = [&](Vec3 v, bool point) {
        if (point) v.z -= a.firstOrder.zPPrime;
        Vec3 q{r[0] * v.x + r[3] * v.y + r[6] * v.z, r[1] * v.x + r[4] * v.y + r[7] * v.z, r[2] * v.x + r[5] * v.y + r[8] * v.z};
        if (point) q.z += a.firstOrder.zPPrime;
        return q;
    };
    for (const auto& film : {std::pair<double, double>{0, 0}, {-9, 5}}) {
        double rx, ry;
        camera.rasterPoint(film.first, film.second, rx, ry);
        const int n = 256;
        double sum = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                CameraRay out;
                if (camera.generateRay(rx, ry, float((i + 0.5) / n), float((j + 0.5) / n), out)) sum += out.weight;
            }
        const double camerasE = sum / (double(n) * n);

        const Vec3 from = toLens({film.first, film.second, camera.filmZ()}, true);
        const Vec3 normal = toLens({0, 0, 1}, false);
        // Cosine-weighted directions inside a cone of half-angle 40 degrees (the exit pupil is seen
        // within 20 degrees of the normal).
        const double bruteE = test::passingProjectedSolidAngle(a.lens, from, normal, 40 * kDeg, 1000);
        EXPECT_NEAR(camerasE / bruteE, 1.0, 0.002) << "film point (" << film.first << ", " << film.second << "): camera "
                                                    << camerasE << ", brute force " << bruteE;
    }
}

// A level camera between a floor 70 mm below it and a ceiling 90 mm above, both striped every 15 mm
// across, lit by a lamp ahead; the lens tilted 6 degrees down and focused at 600 mm (f/2.02), so
// that its plane of focus runs from the floor at about 510 mm out to the ceiling at about 770 mm.
// The stripes are sharp where it crosses each: a band across the picture in its lower and its
// upper half. Each band's row (from the sharpness of the central columns) and its chief ray give a
// depth; the line through the two points is the plane of focus, whose angle and depths are
// returned against the predicted plane's.
struct SharpBands {
    double angleError = 1e9;       // degrees
    double floorZ = 0, ceilingZ = 0, predictedFloorZ = 0, predictedCeilingZ = 0;
};
SharpBands renderSharpBands(const std::string& mode, int spp, std::uint64_t seed = 0) {
    test::TempDir dir;
    const double floorY = -70, ceilingY = 90, tilt = 6, focus = 600;
    const std::string plane = "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-1 Y 0  1 Y 0  1 Y 3  -1 Y 3] "
                              "\"float uv\" [0 0 1 0 1 1 0 1]\n";
    const auto at = [&](double y) { return std::regex_replace(plane, std::regex("Y"), std::to_string(y)); };
    const std::string scene = dir.write(
        "tilt.pbrt",
        "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"" + test::lensPath("dgauss.50mm.dat") +
            "\" \"float focaldistance\" " + std::to_string(focus) + " \"string mode\" \"" + mode + "\" \"float lenstilt\" " +
            std::to_string(tilt) +
            "\nFilm \"image\"\nPixelFilter \"box\"\nIntegrator \"whitted\"\n"
            "WorldBegin\nLightSource \"point\" \"point from\" [0 0 0.6] \"rgb I\" [0.3 0.3 0.3]\n"
            "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 400 \"float vscale\" 1 \"rgb tex1\" [0.9 0.9 0.9] "
            "\"rgb tex2\" [0.05 0.05 0.05]\nMaterial \"matte\" \"texture Kd\" \"c\"\n" +
            at(floorY / 1000) + at(ceilingY / 1000) + "WorldEnd\n");
    const int width = 360, rows = 240;
    RenderSettings settings;
    settings.threads = 2;
    settings.seed = seed;
    const Image im = test::render(scene, width, rows, spp, settings).image;

    RealisticParams p = dgauss(focus);
    p.mode = *parseLensMode(mode);
    p.mount.tiltDegrees = tilt;
    const RealisticCamera camera(p, Transform{}, width, rows, 0.5);
    // In the (-y, z) plane the tilt turns the axis toward +a.
    const Line2 pof = scheimpflugPlaneOfFocus(camera.analysis().firstOrder, camera.analysis().focus.imageZThick, tilt * kDeg);
    SharpBands result;
    const auto predictedZ = [&](double y) { return pof.point.b + (-y - pof.point.a) / pof.direction.a * pof.direction.b; };
    result.predictedFloorZ = predictedZ(floorY);
    result.predictedCeilingZ = predictedZ(ceilingY);

    // Sharpness per row: the squared differences across the stripes over the central 120 columns
    // (where the stripes run nearly up the picture), over the row's mean squared (the lamp lights
    // the near planes more), per stripe edge: the row holds a number of edges proportional to the
    // distance, which goes as 1 / |row - horizon|.
    std::vector<double> e(rows, 0.0);
    for (int y = 0; y < rows; ++y) {
        double g2 = 0, mean = 0;
        for (int x = width / 3; x < 2 * width / 3; ++x) {
            const double g = double(test::lum(im, x + 1, y)) - test::lum(im, x, y);
            g2 += g * g;
            mean += test::lum(im, x, y);
        }
        mean /= width / 3;
        e[y] = mean > 0 ? g2 / (mean * mean) * std::fabs(y + 0.5 - 0.5 * rows) : 0.0;
    }
    // The middle of a band: halfway between the rows where the sharpness crosses half its height
    // above the blurred plane's on either side of its peak (defocus grows linearly with the row
    // either way, as 1 / z does).
    std::vector<double> smooth(rows, 0.0);  // over 5 rows, against the samples' noise
    for (int y = 2; y < rows - 2; ++y)
        for (int dy = -2; dy <= 2; ++dy) smooth[y] += e[y + dy] / 5;
    e = smooth;
    const auto bandRow = [&](int first, int last) {
        const int best = int(std::max_element(e.begin() + first, e.begin() + last) - e.begin());
        // The blurred plane's level: the lower quartile of the rows that see it lit.
        std::vector<double> lit;
        for (int y = first; y < last; ++y)
            if (e[y] > 0) lit.push_back(e[y]);
        std::nth_element(lit.begin(), lit.begin() + lit.size() / 4, lit.end());
        const double floor = lit[lit.size() / 4];
        const double level = 0.5 * (e[best] + floor);
        int lo = best, hi = best;
        while (lo > first && e[lo - 1] > level) --lo;
        while (hi < last - 1 && e[hi + 1] > level) ++hi;
        if (lo == first || hi == last - 1) return -1.0;  // no band inside
        return 0.5 * (lo - (e[lo] - level) / (e[lo] - e[lo - 1]) + hi + (e[hi] - level) / (e[hi] - e[hi + 1]));
    };
    // The depth where the chief ray of the band's central pixel meets its plane.
    const auto depth = [&](double row, double y) {
        CameraRay ray;
        if (row < 0 || !camera.generateRay(0.5 * width, row + 0.5, 0.5f, 0.5f, ray)) return -1.0;
        return ray.origin.z + (y - ray.origin.y) / ray.direction.y * ray.direction.z;
    };
    result.floorZ = depth(bandRow(rows / 2 + 20, rows - 2), floorY);  // clear of the far planes' aliasing
    result.ceilingZ = depth(bandRow(2, rows / 2 - 20), ceilingY);
    if (result.floorZ < 0 || result.ceilingZ < 0) return result;
    const double measured = std::atan2(ceilingY - floorY, result.ceilingZ - result.floorZ);
    const double expected = std::atan2(ceilingY - floorY, result.predictedCeilingZ - result.predictedFloorZ);
    result.angleError = std::fabs(measured - expected) / kDeg;
    return result;
}

TEST(TiltShift, TiltedLensRenderDrawsTheSharpBandsWhereScheimpflugPutsThem) {
    // The thick lens (the rules' own model) within a degree: seen at 0.3-0.7 degrees at 32 samples
    // per pixel over seeds 0-4, the measurement's own error. The exact lens adds its field curvature,
    // which the rules know nothing of: its ceiling band lies 1-1.4% farther than they say (seen at
    // 0.7-1.4 degrees over the same seeds), so it is held to 1.5 degrees and 2% in depth.
    for (const auto& [mode, degrees, depth] :
         {std::tuple<const char*, double, double>{"thick", 1.0, 0.01}, {"exact", 1.5, 0.02}}) {
        const SharpBands b = renderSharpBands(mode, 32);
        const std::string seen = std::string(mode) + ": floor at " + std::to_string(b.floorZ) + " mm (predicted " +
                                 std::to_string(b.predictedFloorZ) + "), ceiling at " + std::to_string(b.ceilingZ) +
                                 " mm (predicted " + std::to_string(b.predictedCeilingZ) + ")";
        EXPECT_LT(b.angleError, degrees) << seen;
        EXPECT_NEAR(b.floorZ, b.predictedFloorZ, depth * b.predictedFloorZ) << seen;
        EXPECT_NEAR(b.ceilingZ, b.predictedCeilingZ, depth * b.predictedCeilingZ) << seen;
    }
}

}  // namespace
}  // namespace lenslab
