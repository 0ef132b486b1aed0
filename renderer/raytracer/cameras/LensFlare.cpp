#include "cameras/LensFlare.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "Render.h"
#include "analysis/GhostAnalysis.h"
#include "core/ColourMatching.h"
#include "trace/ExactTrace.h"
#include "trace/RayTransfer.h"
#include "trace/ThinFilm.h"

namespace lenslab {

namespace {

constexpr double kFlareFirstNm = 395, kFlareStepNm = 30;

bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(std::memory_order_relaxed); }

void throwIfCancelled(const std::atomic<bool>* cancel) {
    if (cancelled(cancel)) throw RenderCancelled();
}

// Reflectance of every surface, from each side, at every flare wavelength, tabulated over the
// cosine of incidence (linear between entries): the thin-film matrices once per frame instead of
// once per ray and surface. Transmittance is 1 - R (the layers are lossless).
class ResponseTables {
public:
    static constexpr int kEntries = 257;

    explicit ResponseTables(const LensSystem& lens) : surfaces_(int(lens.surfaces.size())) {
        table_.resize(std::size_t(surfaces_) * 2 * kFlareWavelengths * kEntries);
        tbb::parallel_for(0, surfaces_ * 2, [&](int entry) {
            const int surface = entry / 2;
            const bool fromScene = entry % 2 == 0;
            for (int w = 0; w < kFlareWavelengths; ++w)
                for (int e = 0; e < kEntries; ++e)
                    at(surface, fromScene, w)[e] =
                        float(surfaceResponse(lens, surface, fromScene, double(e) / (kEntries - 1), flareWavelengthNm(w)).reflectance);
        });
    }

    float reflectance(int surface, bool fromScene, int wavelength, double cosine) const {
        const float* t = table_.data() + index(surface, fromScene, wavelength);
        const double x = std::min(1.0, std::max(0.0, cosine)) * (kEntries - 1);
        const int e = std::min(kEntries - 2, int(x));
        const double f = x - e;
        return float((1 - f) * t[e] + f * t[e + 1]);
    }

private:
    std::size_t index(int surface, bool fromScene, int wavelength) const {
        return ((std::size_t(surface) * 2 + (fromScene ? 0 : 1)) * kFlareWavelengths + wavelength) * kEntries;
    }
    float* at(int surface, bool fromScene, int wavelength) { return table_.data() + index(surface, fromScene, wavelength); }

    int surfaces_;
    std::vector<float> table_;
};

// A ghost's unfolded lens at one waveband, as the tracer's constants (apertures off: the film cuts
// them per pixel), with what each surface's clear aperture and obscuration are.
struct BandLens {
    LensSystem lens;
    std::vector<SurfaceConstants<double>> constants;
    std::vector<double> aperture2, obscuration2;
    int stopStep = -1;
};

BandLens bandLens(const UnfoldedGhost& ghost, double nm) {
    BandLens b;
    b.lens = atWavelength(ghost.lens, nm);
    TraceOptions open;
    open.ignoreApertures = true;
    for (int k = 0; k < int(b.lens.surfaces.size()); ++k) {
        b.constants.push_back(surfaceConstants<double>(b.lens, k, TraceDirection::SceneToFilm, open));
        const Surface& s = b.lens.surfaces[k];
        b.aperture2.push_back(s.apertureRadius * s.apertureRadius);
        b.obscuration2.push_back(s.obscurationRadius * s.obscurationRadius);
    }
    b.stopStep = b.lens.stopIndex;
    return b;
}

// The surface's normal at a point on it (any length, toward +z), as the surface step finds it.
Vec3 normalAt(const SurfaceConstants<double>& s, double x, double y, double z) {
    const double qz = z - s.zVertex;
    if (s.asphericTerms > 0) {
        double sag, g, u;
        asphereSag(x * x + y * y, s, sag, g, u);
        return {g * x, g * y, 1};
    }
    const double c = s.curvature;
    return {c * x, c * y, 1 + s.conicFactor * c * qz};
}

// One ray of a ghost's grid, traced to the film: where it lands (raster), where it crossed the stop
// the first time (in stop radii), the largest share of a clear aperture it used elsewhere and the
// smallest of an obscuration (a mask passes while rim <= 1 and hole >= 1), and the light it
// carries per unit of the source's irradiance and of entrance area, as RGB.
struct FlareVertex {
    float x = 0, y = 0;
    float stopU = 0, stopV = 0, rim = 0, hole = 0;
    Vec3f rgb;
    bool valid = false;
};

struct FlareContext {
    const RealisticCamera& camera;
    const ResponseTables& responses;
    const UnfoldedGhost& ghost;
    double filmZ;
    double frontZ;      // the entrance grid's plane: the front vertex
    double startZ;      // where rays start, in front of every surface
};

// Light arriving along `source` at entrance point (x, y) on the front vertex's plane: the ray and
// the flux per unit area of that plane per unit of the irradiance on a plane facing the source at
// the front vertex.
Ray entranceRay(const FlareContext& c, const FlareSource& source, double x, double y, double& flux) {
    Vec3 d = -1.0 * source.direction;
    if (source.distanceMm > 0) {
        const Vec3 from = Vec3{0, 0, c.frontZ} + source.distanceMm * source.direction;
        d = Vec3{x, y, c.frontZ} - from;
        const double r = length(d);
        d = (1.0 / r) * d;
        flux = std::fabs(d.z) * (source.distanceMm * source.distanceMm) / (r * r);
    } else {
        flux = std::fabs(d.z);
    }
    const double back = (c.startZ - c.frontZ) / -d.z;
    return {Vec3{x, y, c.frontZ} - back * d, d};
}

// Traces one grid ray through the band's unfolded lens: all of it to the film, or (toFilm false,
// the coarse pass) only up to its first crossing of the stop, where `valid` says it got there.
FlareVertex traceFlareRay(const FlareContext& c, const BandLens& b, int band, const FlareSource& source, double x, double y,
                          bool toFilm) {
    FlareVertex v;
    double flux;
    const Ray ray = entranceRay(c, source, x, y, flux);
    double px = ray.origin.x, py = ray.origin.y, pz = ray.origin.z;
    double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
    float light[kFlareWavelengthsPerBand];
    std::fill(light, light + kFlareWavelengthsPerBand, float(flux));
    double rim = 0, hole = INFINITY;
    const int steps = toFilm ? int(b.constants.size()) : b.stopStep + 1;
    for (int k = 0; k < steps; ++k) {
        const double ix = dx, iy = dy, iz = dz;
        if (stepThroughSurface(px, py, pz, dx, dy, dz, b.constants[k]) != BlockReason::None) return v;
        const double r2 = px * px + py * py;
        if (k == b.stopStep) {
            const double radius = std::sqrt(b.aperture2[k]);
            v.stopU = float(px / radius);
            v.stopV = float(py / radius);
        } else {
            rim = std::max(rim, r2 / b.aperture2[k]);
        }
        if (b.obscuration2[k] > 0) hole = std::min(hole, r2 / b.obscuration2[k]);
        if (!toFilm) continue;
        const Vec3 n = normalAt(b.constants[k], px, py, pz);
        const double cosine = std::fabs(ix * n.x + iy * n.y + iz * n.z) / length(n);
        const GhostStep& step = c.ghost.steps[k];
        for (int w = 0; w < kFlareWavelengthsPerBand; ++w) {
            const float r = c.responses.reflectance(step.surface, step.fromScene, band * kFlareWavelengthsPerBand + w, cosine);
            light[w] *= step.reflects ? r : 1 - r;
        }
    }
    v.rim = float(std::sqrt(rim));
    v.hole = float(std::min(std::sqrt(hole), 1e6));
    if (!toFilm) {
        v.valid = true;
        return v;
    }
    const double t = (c.filmZ - pz) / dz;
    double rx, ry;
    c.camera.rasterPoint(px + t * dx, py + t * dy, rx, ry);
    v.x = float(rx);
    v.y = float(ry);
    for (int w = 0; w < kFlareWavelengthsPerBand; ++w)
        v.rgb = v.rgb + light[w] * source.rgbPerWavelength[band * kFlareWavelengthsPerBand + w];
    v.valid = t > 0 && std::fabs(rx) < 1e7 && std::fabs(ry) < 1e7;
    return v;
}

// A ghost's grid at one waveband: (n + 1)^2 vertices over a square of the entrance plane.
struct FlareMesh {
    int n = 0;
    double cellAreaMm2 = 0;
    std::vector<FlareVertex> vertices;
    const FlareVertex& at(int i, int j) const { return vertices[std::size_t(j) * (n + 1) + i]; }
};

// A clear aperture (and its obscuration) as a circle in the stop's plane, in stop radii.
struct ApertureCircle {
    double x = 0, y = 0, radius = 0, obscuration = 0;
    bool passes(double u, double v) const {
        const double r2 = (u - x) * (u - x) + (v - y) * (v - y);
        return r2 <= radius * radius && r2 >= obscuration * obscuration;
    }
};

// The paraxial model's ghost: the stop's opening mapped onto the film, uniform, cut by circles.
struct FlarePatch {
    double centreX = 0, centreY = 0;  // raster
    double scale = 0;                 // raster pixels per stop radius (signed: negative flips it)
    Vec3f irradiance;                 // per unit area of film (mm^2), times the camera's scale
    Vec3f flux;                       // total, for a patch smaller than a pixel
    std::vector<ApertureCircle> clips;
};

// The part of the entrance (a square on the front vertex's plane) whose rays reach the stop's
// opening the first time they cross it: a coarse grid over the front element, kept where it passes,
// widened by a cell. Empty (half < 0) when no ray gets there.
struct EntranceSquare {
    double x0 = 0, y0 = 0, side = -1;
};

EntranceSquare entranceSquare(const FlareContext& c, const BandLens& b, const FlareSource& source, int band,
                              std::uint64_t& rays) {
    constexpr int kCoarse = 32;
    const double front = std::sqrt(b.aperture2[0]) * 1.25;
    const double cell = 2 * front / kCoarse;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int j = 0; j <= kCoarse; ++j)
        for (int i = 0; i <= kCoarse; ++i) {
            const double x = -front + i * cell, y = -front + j * cell;
            const FlareVertex v = traceFlareRay(c, b, band, source, x, y, false);
            ++rays;
            if (!v.valid || v.stopU * v.stopU + v.stopV * v.stopV > 1 || v.rim > 1) continue;
            lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
            lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
        }
    if (!(lo[0] <= hi[0])) return {};
    const double side = std::max(hi[0] - lo[0], hi[1] - lo[1]) + 2 * cell;
    return {0.5 * (lo[0] + hi[0]) - 0.5 * side, 0.5 * (lo[1] + hi[1]) - 0.5 * side, side};
}


// The frame's constants every job and the rasteriser share.
struct FlareFrame {
    const RealisticCamera& camera;
    int width, height;
    double pixelMm;     // film millimetres per pixel (square pixels)
    double scale;       // the camera's factor on irradiance
};

double wavebandCentreNm(int band) {
    double sum = 0;
    for (int w = 0; w < kFlareWavelengthsPerBand; ++w) sum += flareWavelengthNm(band * kFlareWavelengthsPerBand + w);
    return sum / kFlareWavelengthsPerBand;
}

// One ghost of one source, exactly: its meshes per waveband (none where no ray reaches the stop).
std::vector<FlareMesh> exactGhost(const FlareContext& c, const FlareSource& source, std::uint64_t& rays) {
    std::vector<BandLens> bands;
    for (int b = 0; b < kFlareWavebands; ++b) bands.push_back(bandLens(c.ghost, wavebandCentreNm(b)));
    const EntranceSquare square = entranceSquare(c, bands[kFlareWavebands / 2], source, kFlareWavebands / 2, rays);
    std::vector<FlareMesh> meshes;
    if (square.side < 0) return meshes;
    for (int b = 0; b < kFlareWavebands; ++b) {
        FlareMesh m;
        m.n = kFlareGrid;
        const double cell = square.side / m.n;
        m.cellAreaMm2 = cell * cell;
        m.vertices.reserve(std::size_t(m.n + 1) * (m.n + 1));
        for (int j = 0; j <= m.n; ++j)
            for (int i = 0; i <= m.n; ++i)
                m.vertices.push_back(traceFlareRay(c, bands[b], b, source, square.x0 + i * cell, square.y0 + j * cell, true));
        rays += m.vertices.size();
        meshes.push_back(std::move(m));
    }
    return meshes;
}

// A paraxial ray from the front vertex's plane at point p meets a plane of the path at a p + b
// (per axis: the matrices are the same for x and y; b holds the source's direction, or for a point
// source a also its distance).
struct AffineMap {
    double a = 1, b[2] = {0, 0};
};

AffineMap affineTo(const RayTransfer& m, const FlareSource& source) {
    const Vec3& dir = source.direction;
    AffineMap out;
    if (source.distanceMm > 0) {
        const double d = source.distanceMm * dir.z;  // the source's height above the front vertex's plane
        out.a = m.a + m.b / d;
        out.b[0] = -m.b * source.distanceMm * dir.x / d, out.b[1] = -m.b * source.distanceMm * dir.y / d;
    } else {
        out.a = m.a;
        out.b[0] = -m.b * dir.x / dir.z, out.b[1] = -m.b * dir.y / dir.z;
    }
    return out;
}

// One ghost of one source by its ray-transfer matrices (Lee & Eisemann): the film holds the stop's
// opening (q, in stop radii) mapped by film = (a_f / a_s)(q - b_s) + b_f, lit uniformly by E cos / a_f^2,
// cut by every clear aperture and obscuration the path meets, each a circle in the stop's plane.
std::vector<FlarePatch> paraxialGhost(const FlareContext& c, const FlareFrame& f, const FlareSource& source) {
    std::vector<FlarePatch> patches;
    if (!(source.direction.z > 0)) return patches;
    const int stop = c.ghost.lens.stopIndex, last = int(c.ghost.lens.surfaces.size());
    const double stopRadius = c.ghost.lens.surfaces[stop].apertureRadius;
    for (int b = 0; b < kFlareWavebands; ++b) {
        const LensSystem lens = atWavelength(c.ghost.lens, wavebandCentreNm(b));
        const AffineMap toStop = affineTo(rayTransfer(lens, c.frontZ, stop + 1, lens.surfaces[stop].z), source);
        const AffineMap toFilm = affineTo(rayTransfer(lens, c.frontZ, last, c.filmZ), source);
        if (!(std::fabs(toStop.a) > 1e-12)) continue;
        FlarePatch p;
        bool blocked = false;
        for (int k = 0; k < last && !blocked; ++k) {
            if (k == stop) continue;
            const Surface& s = lens.surfaces[k];
            const AffineMap at = affineTo(rayTransfer(lens, c.frontZ, k + 1, s.z), source);
            if (!(std::fabs(at.a) > 1e-12)) {  // every ray meets this surface at the same height
                const double h = std::hypot(at.b[0], at.b[1]);
                blocked = h > s.apertureRadius || h < s.obscurationRadius;
                continue;
            }
            // |at.a p + at.b| <= R with p = (q R_stop - b_s) / a_s: a circle in stop radii.
            const double toStopRadii = toStop.a / (at.a * stopRadius);
            const double cx = (toStop.b[0] - toStop.a * at.b[0] / at.a) / stopRadius;
            const double cy = (toStop.b[1] - toStop.a * at.b[1] / at.a) / stopRadius;
            p.clips.push_back({cx, cy, std::fabs(s.apertureRadius * toStopRadii), std::fabs(s.obscurationRadius * toStopRadii)});
        }
        if (blocked) continue;
        Vec3f rgb;
        for (int w = 0; w < kFlareWavelengthsPerBand; ++w) {
            const int k = b * kFlareWavelengthsPerBand + w;
            double light = 1;
            for (const GhostStep& step : c.ghost.steps) {
                const double r = c.responses.reflectance(step.surface, step.fromScene, k, 1);
                light *= step.reflects ? r : 1 - r;
            }
            rgb = rgb + float(light) * source.rgbPerWavelength[k];
        }
        const double k = toFilm.a / toStop.a;
        f.camera.rasterPoint(toFilm.b[0] - k * toStop.b[0], toFilm.b[1] - k * toStop.b[1], p.centreX, p.centreY);
        p.scale = k * stopRadius / f.pixelMm;
        p.irradiance = float(source.direction.z * f.scale / (toFilm.a * toFilm.a)) * rgb;
        p.flux = float(source.direction.z * f.scale * M_PI * stopRadius * stopRadius / (toStop.a * toStop.a)) * rgb;
        patches.push_back(p);
    }
    return patches;
}

// Adds light to one pixel of the layer, whose rows [y0, y1) this band holds.
struct LayerBand {
    float* rows;  // the layer's row y0
    int y0, y1, width;
    void add(int x, int y, Vec3f v) const {
        if (x < 0 || x >= width || y < y0 || y >= y1) return;
        float* p = rows + (std::size_t(y - y0) * width + x) * 3;
        p[0] += v.x, p[1] += v.y, p[2] += v.z;
    }
};

// The mask at a point of a ghost: inside every clear aperture, outside every obscuration, the
// stop's shape where it first crossed the stop.
double flareMask(const ApertureShape& shape, double u, double v, double rim, double hole) {
    return rim <= 1 && hole >= 1 ? shape.weight(u, v) : 0.0;
}

// A triangle of a mesh on the film (raster pixels): barycentric weights of a point, and whether a
// pixel's centre lies inside.
struct FilmTriangle {
    const FlareVertex &a, &b, &c;
    double inverseArea2;  // 1 / twice the signed area
    bool weights(double px, double py, double& wa, double& wb, double& wc) const {
        wb = ((px - a.x) * (double(c.y) - a.y) - (double(c.x) - a.x) * (py - a.y)) * inverseArea2;
        wc = ((double(b.x) - a.x) * (py - a.y) - (px - a.x) * (double(b.y) - a.y)) * inverseArea2;
        wa = 1 - wb - wc;
        return wa >= 0 && wb >= 0 && wc >= 0;
    }
};

// A triangle's light where no pixel centre falls inside it: shared bilinearly among the four pixels
// around its centre, so that tiny triangles near a caustic leave no pattern of empty pixels.
void splatTriangle(const FilmTriangle& t, double energy, const FlareFrame& f, const LayerBand& layer) {
    const double cx = (t.a.x + t.b.x + t.c.x) / 3.0 - 0.5, cy = (t.a.y + t.b.y + t.c.y) / 3.0 - 0.5;
    const double mask = flareMask(f.camera.params().aperture, (t.a.stopU + t.b.stopU + t.c.stopU) / 3.0,
                                  (t.a.stopV + t.b.stopV + t.c.stopV) / 3.0, (t.a.rim + t.b.rim + t.c.rim) / 3.0,
                                  (t.a.hole + t.b.hole + t.c.hole) / 3.0);
    if (!(mask > 0)) return;
    const int x0 = int(std::floor(cx)), y0 = int(std::floor(cy));
    const double fx = cx - x0, fy = cy - y0;
    const Vec3f light = float(mask * energy / 3) * (t.a.rgb + t.b.rgb + t.c.rgb);
    layer.add(x0, y0, float((1 - fx) * (1 - fy)) * light);
    layer.add(x0 + 1, y0, float(fx * (1 - fy)) * light);
    layer.add(x0, y0 + 1, float((1 - fx) * fy) * light);
    layer.add(x0 + 1, y0 + 1, float(fx * fy) * light);
}

// One triangle of a mesh: its light (per unit entrance area) spread over its area on the film,
// sampled at the pixel centres inside it. A small triangle's light is divided among the centres it
// holds (a triangle of 3 pixels may hold 1 or 5), so that it lands whole.
void rasterizeTriangle(const FlareVertex& a, const FlareVertex& b, const FlareVertex& c, double areaInMm2,
                       const FlareFrame& f, const LayerBand& layer) {
    if (!a.valid || !b.valid || !c.valid) return;
    const double minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
    const double minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
    if (maxY < layer.y0 - 1 || minY > layer.y1 + 1 || maxX < -1 || minX > f.width + 1) return;
    const double area2 = (double(b.x) - a.x) * (double(c.y) - a.y) - (double(c.x) - a.x) * (double(b.y) - a.y);
    const double area = 0.5 * std::fabs(area2);  // square pixels
    if (!(area > 0)) return;
    const FilmTriangle t{a, b, c, 1.0 / area2};
    const double energy = f.scale * areaInMm2 / (f.pixelMm * f.pixelMm);  // per unit of rgb, in pixel values x pixels
    const int rowFirst = int(std::ceil(minY - 0.5)), rowLast = int(std::floor(maxY - 0.5));
    const int columnFirst = int(std::ceil(minX - 0.5)), columnLast = int(std::floor(maxX - 0.5));
    constexpr double kSmall = 16;  // square pixels: below this, centres are counted
    double perCentre = 1 / area;
    if (area < kSmall) {
        int centres = 0;
        double wa, wb, wc;
        for (int y = rowFirst; y <= rowLast; ++y)
            for (int x = columnFirst; x <= columnLast; ++x) centres += t.weights(x + 0.5, y + 0.5, wa, wb, wc);
        if (centres == 0) {
            splatTriangle(t, energy, f, layer);
            return;
        }
        perCentre = 1.0 / centres;
    }
    const ApertureShape& shape = f.camera.params().aperture;
    const int yBegin = std::max(layer.y0, rowFirst), yEnd = std::min(layer.y1 - 1, rowLast);
    const int xBegin = std::max(0, columnFirst), xEnd = std::min(f.width - 1, columnLast);
    for (int y = yBegin; y <= yEnd; ++y)
        for (int x = xBegin; x <= xEnd; ++x) {
            double wa, wb, wc;
            if (!t.weights(x + 0.5, y + 0.5, wa, wb, wc)) continue;
            const double mask = flareMask(shape, wa * a.stopU + wb * b.stopU + wc * c.stopU, wa * a.stopV + wb * b.stopV + wc * c.stopV,
                                          wa * a.rim + wb * b.rim + wc * c.rim, wa * a.hole + wb * b.hole + wc * c.hole);
            if (mask > 0) layer.add(x, y, float(mask * energy * perCentre) * (float(wa) * a.rgb + float(wb) * b.rgb + float(wc) * c.rgb));
        }
}

void rasterizeMesh(const FlareMesh& m, const FlareFrame& f, const LayerBand& layer) {
    const double half = 0.5 * m.cellAreaMm2;
    for (int j = 0; j < m.n; ++j)
        for (int i = 0; i < m.n; ++i) {
            rasterizeTriangle(m.at(i, j), m.at(i + 1, j), m.at(i + 1, j + 1), half, f, layer);
            rasterizeTriangle(m.at(i, j), m.at(i + 1, j + 1), m.at(i, j + 1), half, f, layer);
        }
}

// The stretch of a row of the stop's plane (at height v) inside a circle: [lo, hi], empty when lo > hi.
void narrowToCircle(double cx, double cy, double radius, double v, double& lo, double& hi) {
    const double h2 = radius * radius - (v - cy) * (v - cy);
    if (h2 < 0) {
        hi = -INFINITY;
        return;
    }
    const double h = std::sqrt(h2);
    lo = std::max(lo, cx - h);
    hi = std::min(hi, cx + h);
}

// The patch row by row: each row's pixels inside the stop's disc and every clear aperture are one
// stretch (an intersection of discs), found in closed form; only the shape and the obscurations are
// looked up per pixel.
void rasterizePatch(const FlarePatch& p, const FlareFrame& f, const LayerBand& layer) {
    const double reach = std::fabs(p.scale);
    const ApertureShape& shape = f.camera.params().aperture;
    const auto inHole = [&](double u, double v) {
        return std::any_of(p.clips.begin(), p.clips.end(), [&](const ApertureCircle& c) {
            return c.obscuration > 0 && (u - c.x) * (u - c.x) + (v - c.y) * (v - c.y) < c.obscuration * c.obscuration;
        });
    };
    const auto clipped = [&](double u, double v) {
        return !std::all_of(p.clips.begin(), p.clips.end(), [&](const ApertureCircle& c) { return c.passes(u, v); });
    };
    if (reach < 0.5) {  // under a pixel: all of it in the pixel holding its centre, unless clipped there
        if (!clipped(0, 0)) layer.add(int(std::floor(p.centreX)), int(std::floor(p.centreY)), float(1 / (f.pixelMm * f.pixelMm)) * p.flux);
        return;
    }
    // A pixel's film point back to the stop: the patch's scale, and the film's own flip of x.
    const int yBegin = std::max(layer.y0, int(std::ceil(p.centreY - reach - 0.5)));
    const int yEnd = std::min(layer.y1 - 1, int(std::floor(p.centreY + reach - 0.5)));
    for (int y = yBegin; y <= yEnd; ++y) {
        const double v = (y + 0.5 - p.centreY) / p.scale;
        double lo = -INFINITY, hi = INFINITY;
        narrowToCircle(0, 0, 1, v, lo, hi);
        for (const ApertureCircle& c : p.clips) narrowToCircle(c.x, c.y, c.radius, v, lo, hi);
        if (!(lo <= hi)) continue;
        // u = -(x + 0.5 - centreX) / scale, so x + 0.5 = centreX - u scale.
        const double xa = p.centreX - lo * p.scale - 0.5, xb = p.centreX - hi * p.scale - 0.5;
        const int xBegin = std::max(0, int(std::ceil(std::min(xa, xb))));
        const int xEnd = std::min(f.width - 1, int(std::floor(std::max(xa, xb))));
        for (int x = xBegin; x <= xEnd; ++x) {
            const double u = -(x + 0.5 - p.centreX) / p.scale;
            const double w = shape.weight(u, v);
            if (w > 0 && !inHole(u, v)) layer.add(x, y, float(w) * p.irradiance);
        }
    }
}

}  // namespace

double flareWavelengthNm(int k) { return kFlareFirstNm + kFlareStepNm * k; }

double flareWavelengthEdgeNm(int k) {
    if (k <= 0) return kVisibleFirstNm;
    if (k >= kFlareWavelengths) return kVisibleLastNm;
    return kFlareFirstNm + kFlareStepNm * (k - 0.5);
}

std::vector<GhostPath> selectGhostPaths(const RealisticCamera& camera, const GhostSelection& selection,
                                        const std::atomic<bool>* cancel) {
    throwIfCancelled(cancel);
    if (selection.mode != GhostSelection::Mode::Brightest) return ghostPaths(camera.analysis().lens);
    const GhostAnalysis analysis = analyzeGhosts(camera.analysis(), cancel);
    throwIfCancelled(cancel);
    std::vector<GhostPath> paths;
    for (const GhostImage& g : analysis.ghosts) {
        if (int(paths.size()) == selection.count) break;
        paths.push_back(g.path);
    }
    return paths;
}

std::vector<float> renderLensFlare(const RealisticCamera& camera, int width, int height,
                                   const std::vector<FlareSource>& sources, const std::vector<GhostPath>& paths,
                                   GhostModel model, FlareStats& stats, const std::atomic<bool>* cancel) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<float> layer(std::size_t(width) * height * 3, 0.0f);
    stats = {};
    stats.sources = int(sources.size());
    stats.paths = int(paths.size());
    if (sources.empty() || paths.empty()) return layer;
    const LensSystem& lens = camera.analysis().lens;
    const ResponseTables responses(lens);
    const FlareFrame frame{camera, width, height, camera.params().filmDiagonalMm / std::hypot(double(width), double(height)),
                           camera.exactWeightScale()};
    std::vector<UnfoldedGhost> ghosts;
    for (const GhostPath& p : paths) {
        throwIfCancelled(cancel);
        ghosts.push_back(unfoldGhost(lens, p));
    }

    const std::size_t jobs = sources.size() * ghosts.size();
    std::vector<std::vector<FlareMesh>> meshes(model == GhostModel::Exact ? jobs : 0);
    std::vector<std::vector<FlarePatch>> patches(model == GhostModel::Paraxial ? jobs : 0);
    std::atomic<std::uint64_t> rays{0};
    tbb::parallel_for(std::size_t(0), jobs, [&](std::size_t job) {
        if (cancelled(cancel)) return;
        const FlareSource& source = sources[job / ghosts.size()];
        const FlareContext c{camera, responses, ghosts[job % ghosts.size()], camera.filmZ(), lens.frontZ(),
                             lens.frontZ() + lens.surfaces.front().apertureRadius + 1};
        if (model == GhostModel::Paraxial) {
            patches[job] = paraxialGhost(c, frame, source);
            return;
        }
        std::uint64_t traced = 0;
        meshes[job] = exactGhost(c, source, traced);
        rays += traced;
    });
    throwIfCancelled(cancel);
    stats.raysTraced = rays;

    // The film in bands of rows, each band drawing every ghost in the same order: the sums come out
    // the same bits whatever the threads.
    constexpr int kBandRows = 32;
    const int bands = (height + kBandRows - 1) / kBandRows;
    tbb::parallel_for(0, bands, [&](int band) {
        if (cancelled(cancel)) return;
        const int y0 = band * kBandRows;
        const LayerBand part{layer.data() + std::size_t(y0) * width * 3, y0, std::min(height, y0 + kBandRows), width};
        for (const auto& job : meshes)
            for (const FlareMesh& m : job) rasterizeMesh(m, frame, part);
        for (const auto& job : patches)
            for (const FlarePatch& p : job) rasterizePatch(p, frame, part);
    });
    throwIfCancelled(cancel);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return layer;
}

}  // namespace lenslab
