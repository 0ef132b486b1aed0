#include "render/FlareSources.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/ColourMatching.h"
#include "firstorder/ChiefRay.h"
#include "trace/ExactTrace.h"

namespace lenslab {

namespace {

// An emitter (or a patch of one) seen from the lens, in world space.
struct Candidate {
    Vec3f direction;         // unit, toward it
    double distance = 0;     // world units; 0: at infinity
    double nearest = 0;      // its nearest point (the light's own surface must not hide it)
    Vec3f irradiance;        // on a plane facing it
    double solidAngle = 0;   // 0: a point or a single direction
    bool delta = false;
    const char* what = "";
};

// Light sampled from p over a light's surface or the sky, gathered by direction into patches.
struct Patch {
    Vec3f irradiance;
    double x = 0, y = 0, z = 0, distance = 0, weight = 0, nearest = INFINITY;
};

void gatherPatches(const Light& light, Vec3f p, int grid, std::map<std::tuple<int, int, int>, Patch>& patches) {
    const double perSample = 1.0 / (grid * grid);
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            LightSample s;
            if (!light.sample(p, (i + 0.5f) / grid, (j + 0.5f) / grid, s) || !(s.pdf > 0)) continue;
            const Vec3f e = float(perSample / s.pdf) * s.radiance;
            const float y = luminance(e);
            if (!(y > 0) || !std::isfinite(y)) continue;
            const auto cell = [](float c) { return int(std::lround(c / kFlarePatchRadians)); };
            Patch& patch = patches[{cell(s.wi.x), cell(s.wi.y), cell(s.wi.z)}];
            patch.irradiance += e;
            patch.x += y * s.wi.x, patch.y += y * s.wi.y, patch.z += y * s.wi.z;
            patch.distance += y * (std::isfinite(s.distance) ? s.distance : 0.0);
            patch.nearest = std::min(patch.nearest, std::isfinite(s.distance) ? double(s.distance) : 0.0);
            patch.weight += y;
        }
}

using Patches = std::map<std::tuple<int, int, int>, Patch>;

Candidate patchCandidate(const Patch& patch, double solidAngle, const char* what) {
    return {normalize(Vec3f{float(patch.x), float(patch.y), float(patch.z)}), patch.distance / patch.weight, patch.nearest,
            patch.irradiance, solidAngle, false, what};
}

Vec3f patchDirection(const Patch& p) { return normalize(Vec3f{float(p.x), float(p.y), float(p.z)}); }

// Patches within kFlareCompactRadians of a brighter one join it: a small area light, or the sun of
// an environment map, is one source; a large one gives a source per region of that size. A cluster's
// radiance is at most its brightest patch's, its first: a patch under kFlareBrightRadiance only
// joins a cluster, never starts one (one that would be dropped), so a dim sky costs no clustering.
void addClusters(const Patches& patches, const char* what, std::vector<Candidate>& out) {
    constexpr double kPatchSolidAngle = kFlarePatchRadians * kFlarePatchRadians;
    std::vector<const Patch*> order;
    for (const auto& [cell, patch] : patches) order.push_back(&patch);
    std::stable_sort(order.begin(), order.end(), [](const Patch* a, const Patch* b) { return a->weight > b->weight; });
    std::vector<Patch> clusters;
    std::vector<int> counts;
    for (const Patch* p : order) {
        const Vec3f d = patchDirection(*p);
        std::size_t k = 0;
        while (k < clusters.size() && std::acos(std::min(1.0f, dot(d, patchDirection(clusters[k])))) >= kFlareCompactRadians) ++k;
        if (k == clusters.size()) {
            if (p->weight < kFlareBrightRadiance * kPatchSolidAngle) continue;
            clusters.emplace_back();
            counts.push_back(0);
        }
        Patch& c = clusters[k];
        c.irradiance += p->irradiance;
        c.x += p->x, c.y += p->y, c.z += p->z, c.distance += p->distance, c.weight += p->weight;
        c.nearest = std::min(c.nearest, p->nearest);
        ++counts[k];
    }
    for (std::size_t k = 0; k < clusters.size(); ++k)
        out.push_back(patchCandidate(clusters[k], counts[k] * kPatchSolidAngle, what));
}

std::vector<Candidate> candidates(const SceneGeometry& geometry, Vec3f p) {
    std::vector<Candidate> out;
    Patches sky;
    for (const auto& light : geometry.lights()) {
        if (light->isDelta()) {
            LightSample s;
            if (!light->sample(p, 0.5f, 0.5f, s) || !(luminance(s.radiance) > 0)) continue;
            const bool distant = !std::isfinite(s.distance);
            const double distance = distant ? 0.0 : double(s.distance);
            out.push_back({s.wi, distance, distance, s.radiance, 0, true, distant ? "distant light" : "point light"});
        } else if (light->isInfinite()) {
            gatherPatches(*light, p, 64, sky);
        } else {
            Patches patches;
            gatherPatches(*light, p, 4, patches);
            addClusters(patches, "area light", out);
        }
    }
    addClusters(sky, "environment map", out);
    return out;
}

// Whether a distant object in lens-space direction d images onto the frame widened by half its size
// on every side, by the chief ray traced to the film (apertures open).
bool inOrNearFrame(const RealisticCamera& camera, int width, int height, const Vec3& d) {
    if (!(d.z > 0)) return false;
    const LensSystem& lens = camera.analysis().lens;
    const double field = std::acos(std::min(1.0, d.z)) * 180 / M_PI;
    const std::optional<Ray> chief = chiefRay(lens, field);
    if (!chief) return false;
    TraceOptions open;
    open.ignoreApertures = true;
    const TraceResult r = traceRay(lens, *chief, TraceDirection::SceneToFilm, open);
    if (!r.ok()) return false;
    const double t = (camera.filmZ() - r.ray.origin.z) / r.ray.direction.z;
    const double height2 = std::hypot(r.ray.origin.x + t * r.ray.direction.x, r.ray.origin.y + t * r.ray.direction.y);
    const double across = std::hypot(d.x, d.y);
    double rx, ry;
    camera.rasterPoint(across > 0 ? -height2 * d.x / across : 0.0, across > 0 ? -height2 * d.y / across : 0.0, rx, ry);
    return rx >= -0.5 * width && rx <= 1.5 * width && ry >= -0.5 * height && ry <= 1.5 * height;
}

// The source's light per flare wavelength: the spectral film's response to each 1 nm band of its
// spectrum, summed over the bands each flare wavelength stands for (together: its RGB).
std::array<Vec3f, kFlareWavelengths> spectralShares(const SpectralSensor& sensor, Vec3f rgb) {
    std::array<Vec3f, kFlareWavelengths> shares{};
    int k = 0;
    for (int nm = kVisibleFirstNm; nm <= kVisibleLastNm; ++nm) {
        while (k + 1 < kFlareWavelengths && nm >= flareWavelengthEdgeNm(k + 1)) ++k;
        shares[k] += sensor.toRgb(rgb, WavelengthSample{double(nm), nm - kVisibleFirstNm, 1.0f});
    }
    return shares;
}

}  // namespace

std::vector<FlareSource> findFlareSources(const SceneGeometry& geometry, const RealisticCamera& camera, int width,
                                          int height, const SpectralSensor& sensor, bool brightOnly, float time) {
    const double unit = camera.params().cameraUnitMm, originZ = camera.lensSpaceOriginZ();
    const double frontZ = camera.analysis().lens.frontZ();
    const Transform& toWorld = camera.cameraToWorld();
    const Transform toCamera = inverse(toWorld);
    const Vec3f front = transformPoint(toWorld, Vec3f{0, 0, float((frontZ - originZ) / unit)});
    const double pixelMm = camera.params().filmDiagonalMm / std::hypot(double(width), double(height));
    const double pixelSolidAngle = std::pow(pixelMm / camera.analysis().firstOrder.efl, 2);

    std::vector<Candidate> kept;
    for (const Candidate& c : candidates(geometry, front)) {
        const double radiance = luminance(c.irradiance) / std::max(c.solidAngle, pixelSolidAngle);
        if ((brightOnly || !c.delta) && radiance < kFlareBrightRadiance) continue;
        const Vec3f d = normalize(transformVector(toCamera, c.direction));
        if (!inOrNearFrame(camera, width, height, {d.x, d.y, d.z})) continue;
        const float reach = c.nearest > 0 ? float(c.nearest * 0.999) : INFINITY;
        if (geometry.occluded(front, c.direction, reach, time)) continue;
        kept.push_back(c);
    }
    std::sort(kept.begin(), kept.end(),
              [](const Candidate& a, const Candidate& b) { return luminance(a.irradiance) > luminance(b.irradiance); });
    if (kept.size() > std::size_t(kMostFlareSources)) kept.resize(kMostFlareSources);

    std::vector<FlareSource> out;
    for (const Candidate& c : kept) {
        FlareSource s;
        const Vec3f d = normalize(transformVector(toCamera, c.direction));
        s.direction = normalize(Vec3{d.x, d.y, d.z});
        if (c.distance > 0) {
            const Vec3f at = transformPoint(toCamera, front + float(c.distance) * c.direction);
            s.distanceMm = length(Vec3{at.x * unit, at.y * unit, at.z * unit + originZ - frontZ});
        }
        s.rgbPerWavelength = spectralShares(sensor, c.irradiance);
        s.what = c.what;
        out.push_back(s);
    }
    return out;
}

}  // namespace lenslab
