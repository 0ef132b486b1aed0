// Lens flare against brute force: the ghosts of a point light through dgauss.50mm with bare
// surfaces, rendered from the unfolded paths (cameras/LensFlare.h), against a Monte Carlo trace
// written here that shares nothing with it: rays from the light through the front element, each
// surface choosing reflection or refraction with Fresnel's probability, walking the surfaces
// forward or back as the light turns, the paths with exactly two reflections landing on the film.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cameras/GhostSelection.h"
#include "cameras/LensFlare.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

struct V {
    double x, y, z;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V unit(V a) { return (1 / std::sqrt(dot(a, a))) * a; }

// The nearest hit ahead of (o, d) on surface k (a sphere's cap at its vertex, or a plane), or false.
bool hitSurface(const Surface& s, V o, V d, V& at, V& normal) {
    if (s.curvature == 0) {
        const double t = (s.z - o.z) / d.z;
        if (!(t > 1e-9)) return false;
        at = o + t * d;
        normal = {0, 0, 1};
        return true;
    }
    const V centre{0, 0, s.z - s.radius};
    const V oc{o.x - centre.x, o.y - centre.y, o.z - centre.z};
    const double b = dot(oc, d), c = dot(oc, oc) - s.radius * s.radius, disc = b * b - c;
    if (disc < 0) return false;
    // The cap: the root on the vertex's side of the centre.
    for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
        if (!(t > 1e-9)) continue;
        const V p = o + t * d;
        if ((p.z - centre.z) * s.radius > 0) {
            at = p;
            normal = unit({p.x - centre.x, p.y - centre.y, p.z - centre.z});
            return true;
        }
    }
    return false;
}

// Fresnel's unpolarised reflectance and the refracted direction (false: total internal reflection).
double fresnel(V d, V n, double n1, double n2, V& refracted) {
    double cosi = -dot(d, n);
    if (cosi < 0) {
        n = -1.0 * n;
        cosi = -cosi;
    }
    const double eta = n1 / n2, k = 1 - eta * eta * (1 - cosi * cosi);
    if (k < 0) return 1;
    const double cost = std::sqrt(k);
    refracted = unit(eta * d + (eta * cosi - cost) * n);
    const double rs = (n1 * cosi - n2 * cost) / (n1 * cosi + n2 * cost), rp = (n2 * cosi - n1 * cost) / (n2 * cosi + n1 * cost);
    return 0.5 * (rs * rs + rp * rp);
}

// Energy per pixel (irradiance times pixel area) of the light's two-reflection paths.
std::vector<double> bruteForceGhosts(const RealisticCamera& camera, int width, int height, V light, double irradiance,
                                     int rays) {
    const LensSystem& lens = camera.analysis().lens;
    const int n = int(lens.surfaces.size());
    const double half = lens.surfaces[0].apertureRadius, area = 4 * half * half;
    const double distance = std::sqrt(dot(light, light));
    std::vector<double> film(std::size_t(width) * height, 0.0);
    std::mt19937_64 rng(2011);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int r = 0; r < rays; ++r) {
        const V target{(2 * u01(rng) - 1) * half, (2 * u01(rng) - 1) * half, 0};
        V d = unit({target.x - light.x, target.y - light.y, target.z - light.z});
        const V toTarget{target.x - light.x, target.y - light.y, target.z - light.z};
        // Flux through the patch of the front vertex's plane: I cos / r^2 dA, with I = E D^2.
        const double flux = irradiance * distance * distance * std::fabs(d.z) / dot(toTarget, toTarget) * area / rays;
        V o = light;
        int k = 0, step = 1, reflections = 0;
        bool alive = true;
        while (alive && k >= 0 && k < n) {
            const Surface& s = lens.surfaces[k];
            V at, normal;
            if (!hitSurface(s, o, d, at, normal) || at.x * at.x + at.y * at.y > s.apertureRadius * s.apertureRadius) break;
            const double nScene = k == 0 ? 1.0 : lens.surfaces[k - 1].indexAfter, nFilm = s.indexAfter;
            V refracted;
            const double R = step > 0 ? fresnel(d, normal, nScene, nFilm, refracted) : fresnel(d, normal, nFilm, nScene, refracted);
            o = at;
            if (u01(rng) < R) {
                d = unit(d + (-2 * dot(d, normal)) * normal);
                step = -step;
                alive = ++reflections <= 2;
            } else {
                d = refracted;
            }
            k += step;
        }
        if (!alive || k != n || reflections != 2) continue;
        const double t = (camera.filmZ() - o.z) / d.z;
        double rx, ry;
        camera.rasterPoint(o.x + t * d.x, o.y + t * d.y, rx, ry);
        const int px = int(std::floor(rx)), py = int(std::floor(ry));
        if (px >= 0 && px < width && py >= 0 && py < height) film[std::size_t(py) * width + px] += flux;
    }
    return film;
}

double blockCorrelation(const std::vector<double>& a, const std::vector<double>& b, int width, int height, int block) {
    std::vector<double> x, y;
    for (int by = 0; by + block <= height; by += block)
        for (int bx = 0; bx + block <= width; bx += block) {
            double sa = 0, sb = 0;
            for (int j = 0; j < block; ++j)
                for (int i = 0; i < block; ++i) {
                    sa += a[std::size_t(by + j) * width + bx + i];
                    sb += b[std::size_t(by + j) * width + bx + i];
                }
            x.push_back(sa);
            y.push_back(sb);
        }
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
    mx /= x.size(), my /= y.size();
    double sxy = 0, sxx = 0, syy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
    }
    return sxy / std::sqrt(sxx * syy);
}

RealisticCamera bareDgauss(int width, int height) {
    LensTable table = readLensTable(test::lensPath("dgauss.50mm.dat"));
    for (LensTableRow& row : table.rows) row.coating = "none";
    RealisticParams p;
    p.lens = buildLensSystem(table);
    p.settings.fstop = Setting{4, "fstop"};
    p.settings.focusDistance = Setting{INFINITY, "focus"};
    p.filmDiagonalMm = 43.27;
    return RealisticCamera(p, Transform{}, width, height, 0);
}

TEST(LensFlare, ExactGhostsOfAPointLightMatchBruteForce) {
    const int width = 96, height = 64;
    const RealisticCamera camera = bareDgauss(width, height);
    const V light{180, 120, 3000};  // lens space, mm: 4 degrees off axis
    FlareSource source;
    source.direction = normalize(Vec3{light.x, light.y, light.z});
    source.distanceMm = std::sqrt(dot(light, light));
    for (Vec3f& c : source.rgbPerWavelength) c = Vec3f{1, 1, 1} / float(kFlareWavelengths);
    FlareStats stats;
    const std::vector<float> layer = renderLensFlare(camera, width, height, {source}, ghostPaths(camera.analysis().lens),
                                                     GhostModel::Exact, stats);
    EXPECT_EQ(stats.paths, 45);
    const double pixelArea = std::pow(camera.params().filmDiagonalMm / std::hypot(width, height), 2);
    std::vector<double> rendered(std::size_t(width) * height);
    for (std::size_t i = 0; i < rendered.size(); ++i) {
        EXPECT_NEAR(layer[3 * i], layer[3 * i + 1], 1e-6 * layer[3 * i] + 1e-30);  // grey light, grey ghosts (bare)
        rendered[i] = layer[3 * i] * pixelArea;
    }
    const std::vector<double> brute = bruteForceGhosts(camera, width, height, light, 1.0, 3'000'000);
    double totalRendered = 0, totalBrute = 0;
    for (std::size_t i = 0; i < rendered.size(); ++i) totalRendered += rendered[i], totalBrute += brute[i];
    EXPECT_GT(totalBrute, 0);
    EXPECT_NEAR(totalRendered / totalBrute, 1, 0.03);
    EXPECT_GE(blockCorrelation(rendered, brute, width, height, 8), 0.95);
}

}  // namespace
}  // namespace lenslab
