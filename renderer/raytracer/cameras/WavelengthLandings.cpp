// Several wavelengths per camera sample through a dispersive lens (docs/spectral.md): the ray made at
// the sample's own wavelength leaves the lens as one scene ray; each other wavelength would have
// made that same scene ray from another film point, found by tracing it back through the lens at
// that wavelength. The frame weighs the wavelengths by the densities returned here (spectral MIS)
// and scores each where it lands. A wavelength's density is that of the pupil region the camera
// samples for it (its band's, SpectralExitPupilBounds).
#include <cmath>

#include "cameras/RealisticCamera.h"
#include "firstorder/ExitPupilBounds.h"

namespace lenslab {

namespace {

constexpr double kNoDensity = 0;

// Scratch for the backward traces: one ray per (sample, other wavelength).
struct BackwardBatch {
    RayBatch rays;
    std::vector<std::uint16_t> bands;
    std::vector<std::size_t> landingOf;  // index into the caller's landings
    std::vector<double> shape;           // a shaped stop's transmission along each
    std::vector<double> filmX, filmY, aimX, aimY, cosTheta, half, nm;
    PupilSampleBatch regions;
};

}  // namespace

void RealisticCamera::generateSpectralRays(const CameraSample* samples, std::size_t n, const double* wavelengthsNm,
                                           int perSample, CameraRay* out, FilmLanding* landings) const {
    thread_local ExactRayBatch b;
    makeRays(samples, n, out, b);
    // Thick-lens rays (no dispersion) and blocked ones land every wavelength on their own film point.
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < perSample; ++k)
            landings[i * perSample + k] = {samples[i].rasterX, samples[i].rasterY, 1.0, double(out[i].weight)};
    if (!params_.spectral || b.sampleOf.empty()) return;
    // The exact rays: the own wavelength's density is that of the pupil sample, per unit ray measure
    // (the weight is cos^4 A / dz^2 times the scale: its inverse times the scale).
    for (std::size_t k = 0; k < b.sampleOf.size(); ++k) {
        const std::size_t i = b.sampleOf[k];
        if (!(out[i].weight > 0)) continue;
        FilmLanding& own = landings[i * perSample];
        own.density = weightScaleExact_ / b.weights[k];
        own.response = double(out[i].weight) * own.density;
    }
    landOtherWavelengths(b, wavelengthsNm, perSample, landings);
}

void RealisticCamera::landOtherWavelengths(const ExactRayBatch& b, const double* wavelengthsNm, int perSample,
                                           FilmLanding* landings) const {
    thread_local BackwardBatch back;
    const LensSystem& lens = analysis_.lens;
    // Far enough ahead of the front vertex to lie in front of any front surface's cap.
    const double startZ = lens.frontZ() + 2 * lens.surfaces.front().apertureRadius + 1;
    back.rays.resize(b.sampleOf.size() * (perSample - 1));
    back.bands.resize(back.rays.size());
    back.nm.resize(back.rays.size());
    back.landingOf.resize(back.rays.size());
    std::size_t m = 0;
    for (std::size_t k = 0; k < b.sampleOf.size(); ++k) {
        const std::size_t i = b.sampleOf[k];
        if (!(landings[i * perSample].density > 0)) continue;  // blocked at its own wavelength
        const Ray exit = b.rays.get(k);
        if (!(exit.direction.z > 0)) continue;
        const Ray incoming{pointAt(exit, (startZ - exit.origin.z) / exit.direction.z), -1.0 * exit.direction};
        for (int w = 1; w < perSample; ++w) {
            const std::size_t at = i * perSample + w;
            landings[at].density = landings[at].response = kNoDensity;
            back.rays.set(m, incoming);
            back.nm[m] = wavelengthsNm[at];
            back.bands[m] = etasBack_.band(back.nm[m]);
            back.landingOf[m++] = at;
        }
    }
    back.rays.resize(m);
    back.shape.assign(m, 1.0);
    if (m == 0) return;
    if (params_.aperture.isCircular()) {
        traceBatch(lens, back.rays, TraceDirection::SceneToFilm, etasBack_, back.bands.data());
    } else {
        for (std::size_t r = 0; r < m; ++r) {  // a shaped stop is met ray by ray
            const TraceResult t = traceShaped(bandLenses_[back.bands[r]], back.rays.get(r), TraceDirection::SceneToFilm,
                                              back.shape[r]);
            back.rays.set(r, t.ray);
            back.rays.blocked[r] = t.ok() && back.shape[r] > 0 ? BlockReason::None : BlockReason::ClippedByStop;
        }
    }
    // Where each passing ray meets the film and the aiming plane; the region the camera samples there.
    for (auto* v : {&back.filmX, &back.filmY, &back.aimX, &back.aimY, &back.cosTheta, &back.half}) v->resize(m);
    const double filmZ = filmZExact_, aimZ = bounds_.aimZ;
    for (std::size_t r = 0; r < m; ++r) {
        const Ray ray = back.rays.get(r);
        const bool toFilm = back.rays.blocked[r] == BlockReason::None && ray.direction.z < 0;
        const double toF = toFilm ? (filmZ - ray.origin.z) / ray.direction.z : 0.0;
        const double toA = toFilm ? (aimZ - ray.origin.z) / ray.direction.z : 0.0;
        back.filmX[r] = ray.origin.x + toF * ray.direction.x;
        back.filmY[r] = ray.origin.y + toF * ray.direction.y;
        back.aimX[r] = ray.origin.x + toA * ray.direction.x;
        back.aimY[r] = ray.origin.y + toA * ray.direction.y;
        back.cosTheta[r] = toFilm ? -ray.direction.z : 0.0;
        back.half[r] = 0.5;
    }
    sampleSpectralExitPupils(spectralBounds_, m, back.filmX.data(), back.filmY.data(), back.half.data(), back.half.data(),
                             back.nm.data(), back.regions);
    const double dz = aimZ - filmZ;
    for (std::size_t r = 0; r < m; ++r) {
        const double c = back.cosTheta[r], fx = back.filmX[r], fy = back.filmY[r], area = back.regions.area[r];
        // The camera makes this ray from (fx, fy) only where the exact lens is used there and the
        // ray's aiming point lies in the region it samples.
        if (!(c > 0) || !(area > 0) || modes_.thickAt(std::sqrt(fx * fx + fy * fy)) ||
            !insideExitPupilBounds(spectralBounds_.at(back.nm[r]), fx, fy, back.aimX[r], back.aimY[r]))
            continue;
        FilmLanding& l = landings[back.landingOf[r]];
        rasterPoint(fx, fy, l.rasterX, l.rasterY);
        l.density = dz * dz / (area * (c * c) * (c * c));
        l.response = weightScaleExact_ * back.shape[r];
    }
}

}  // namespace lenslab
