#include "RealisticCamera.h"

#include <cmath>
#include <cstdio>

#include "Aperture.h"
#include "ExactTrace.h"
#include "OpticsError.h"
#include "RayBatch.h"
#include "Sampling.h"

namespace lenslab {

namespace {

std::string num(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

// The f-number whose stop opening is `diameter` (pbrt-v3 scenes give the opening itself).
double fstopForStopDiameter(const LensSystem& lens, double diameter) {
    const FirstOrder fo = computeFirstOrder(lens);
    const ApertureRange range = computeApertureRange(lens, fo);
    if (!(diameter > 0)) throw OpticsError("aperture diameter must be positive");
    if (diameter >= range.stopDiameterMax) return range.fstopMin;  // pbrt-v3 clamps to the widest too
    double lo = std::log(range.fstopMin), hi = std::log(range.fstopMax);
    for (int it = 0; it < 60; ++it) {  // the opening shrinks as the f-number grows
        const double mid = 0.5 * (lo + hi);
        (stopDiameterForFstop(lens, fo, range, std::exp(mid)) > diameter ? lo : hi) = mid;
    }
    return std::exp(0.5 * (lo + hi));
}

double cos4(double c) { return (c * c) * (c * c); }

}  // namespace

RealisticCamera::RealisticCamera(const RealisticParams& params, const Transform& cameraToWorld, int width, int height,
                                 double filmMarginPixels)
    : params_(params), cameraToWorld_(cameraToWorld), width_(width), height_(height) {
    if (!(params.filmDiagonalMm > 0 && params.filmDiagonalMm < 1e4))
        throw OpticsError("film diagonal must lie in (0, 10000) mm, got " + num(params.filmDiagonalMm));
    if (!(params.exposureTime > 0)) throw OpticsError("exposure time (shutterclose) must be positive");
    const double diag = std::hypot(double(width), double(height));
    halfWidthMm_ = 0.5 * params.filmDiagonalMm * width / diag;
    halfHeightMm_ = 0.5 * params.filmDiagonalMm * height / diag;

    const LensSystem lens = loadLensSystem(params.lensPath);
    std::optional<double> fstop = params.fstop;
    if (!fstop && params.stopDiameterMm) fstop = fstopForStopDiameter(lens, *params.stopDiameterMm);
    if (params.focusFromFilm) {
        // Object distance from the film = focus distance: the film position depends on the focus,
        // so iterate (the film moves by far less than the distance).
        double filmZ = computeFirstOrder(lens).zFPrime;
        for (int it = 0; it < 8; ++it) {
            const double fromVertex = params.focusDistanceMm + filmZ - lens.frontZ();
            analysis_ = analyzeLens(lens, fstop, fromVertex);
            const double next = params.approximate ? analysis_.focus.imageZThick : analysis_.focus.imageZExact;
            if (std::fabs(next - filmZ) < 1e-9) break;
            filmZ = next;
        }
    } else {
        analysis_ = analyzeLens(lens, fstop, params.focusDistanceMm);
    }
    filmZ_ = params.approximate ? analysis_.focus.imageZThick : analysis_.focus.imageZExact;
    if (!(filmZ_ < analysis_.lens.rearZ()))
        throw OpticsError("the film would sit at z = " + num(filmZ_) + " mm, in front of the rear vertex");

    const double pixelMm = params.filmDiagonalMm / diag;
    const double maxRadius = 0.5 * params.filmDiagonalMm + (filmMarginPixels + 1) * pixelMm;
    double centreWeight;
    if (params.approximate) {
        const Pupil& xp = analysis_.pupils.exit;
        if (!(xp.z > filmZ_)) throw OpticsError("the exit pupil lies behind the film; the thick-lens model cannot aim at it");
        const double dz = xp.z - filmZ_;
        centreWeight = M_PI * 0.25 * xp.diameter * xp.diameter / (dz * dz);
    } else {
        bounds_ = computeExitPupilBounds(analysis_.lens, filmZ_, maxRadius);
        const double dz = bounds_.aimZ - filmZ_;
        centreWeight = sampleExitPupil(bounds_, 0, 0, 0.5, 0.5).area / (dz * dz);
    }
    weightScale_ = params.simpleWeighting ? (centreWeight > 0 ? 1.0 / centreWeight : 0.0) : params.exposureTime;
}

void RealisticCamera::filmPoint(double rasterX, double rasterY, double& x, double& y) const {
    const double sx = 2.0 * rasterX / width_ - 1.0;   // -1 left, +1 right
    const double sy = 1.0 - 2.0 * rasterY / height_;  // +1 top, -1 bottom
    x = -sx * halfWidthMm_;
    y = -sy * halfHeightMm_;
}

double RealisticCamera::aim(double rasterX, double rasterY, float u1, float u2, Ray& ray) const {
    double fx, fy;
    filmPoint(rasterX, rasterY, fx, fy);
    const Vec3 from{fx, fy, filmZ_};
    Vec3 target;
    double area;
    if (params_.approximate) {
        float dx, dy;
        concentricDisk(u1, u2, dx, dy);
        const Pupil& xp = analysis_.pupils.exit;
        target = {0.5 * xp.diameter * dx, 0.5 * xp.diameter * dy, xp.z};
        area = M_PI * 0.25 * xp.diameter * xp.diameter;
    } else {
        const PupilSample s = sampleExitPupil(bounds_, fx, fy, u1, u2);
        if (!(s.area > 0)) return 0;
        target = s.point;
        area = s.area;
    }
    const Vec3 d = target - from;
    ray = {from, (1.0 / length(d)) * d};
    // Irradiance from a patch dA of the aiming plane: L cos^2 / dist^2 dA = L cos^4 / dz^2 dA.
    const double dz = target.z - filmZ_;
    return cos4(ray.direction.z) * area / (dz * dz) * weightScale_;
}

bool RealisticCamera::finish(const Ray& lensRay, double weight, CameraRay& out) const {
    const Vec3f o{float(lensRay.origin.x * 1e-3), float(lensRay.origin.y * 1e-3), float(lensRay.origin.z * 1e-3)};
    const Vec3f dir{float(lensRay.direction.x), float(lensRay.direction.y), float(lensRay.direction.z)};
    out.origin = transformPoint(cameraToWorld_, o);
    out.direction = normalize(transformVector(cameraToWorld_, dir));
    out.weight = float(weight);
    if (!std::isfinite(out.weight)) out.weight = 0;
    return out.weight > 0;
}

bool RealisticCamera::generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const {
    Ray ray;
    const double weight = aim(rasterX, rasterY, u1, u2, ray);
    if (!(weight > 0)) return false;
    const TraceResult r = params_.approximate ? traceThick(analysis_.thick, ray, TraceDirection::FilmToScene)
                                              : traceRay(analysis_.lens, ray, TraceDirection::FilmToScene);
    return r.ok() && finish(r.ray, weight, out);
}

void RealisticCamera::generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const {
    if (params_.approximate) {
        Camera::generateRays(samples, n, out);
        return;
    }
    thread_local RayBatch batch;
    thread_local std::vector<double> weights;
    batch.resize(n);
    weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Ray ray{{0, 0, filmZ_}, {0, 0, 1}};
        weights[i] = aim(samples[i].rasterX, samples[i].rasterY, samples[i].u1, samples[i].u2, ray);
        batch.set(i, ray);
    }
    traceBatch(analysis_.lens, batch, TraceDirection::FilmToScene);
    for (std::size_t i = 0; i < n; ++i) {
        out[i].weight = 0;
        if (weights[i] > 0 && batch.blocked[i] == BlockReason::None) finish(batch.get(i), weights[i], out[i]);
    }
}

std::map<std::string, std::string> RealisticCamera::describe() const {
    const LensAnalysis& a = analysis_;
    return {{"camera", "realistic"},
            {"lensFile", params_.lensPath},
            {"lensName", a.lens.name},
            {"mode", params_.approximate ? "approximate" : "accurate"},
            {"fstop", num(a.fstop)},
            {"stopDiameterMm", num(a.stopDiameter)},
            {"focusDistanceMm", a.focus.infinity ? "inf" : num(a.focus.objectZ - a.lens.frontZ())},
            {"filmDiagonalMm", num(params_.filmDiagonalMm)},
            {"filmZMm", num(filmZ_)},
            {"eflMm", num(a.firstOrder.efl)},
            {"exitPupilZMm", num(a.pupils.exit.z)},
            {"exitPupilDiameterMm", num(a.pupils.exit.diameter)},
            {"exposureTimeS", num(params_.exposureTime)},
            {"weighting", params_.simpleWeighting ? "simple (centre = 1)" : "radiometric (cos^4 A / d^2 * t)"},
            {"units", "lens mm, world m"}};
}

}  // namespace lenslab
