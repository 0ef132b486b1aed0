#include "cameras/RealisticCamera.h"

#include <cmath>
#include <limits>

#include "analysis/RelativeIllumination.h"
#include "firstorder/Aperture.h"
#include "trace/ExactTrace.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "prescription/Wavelength.h"
#include "firstorder/PbrtPupilBox.h"
#include "trace/RayBatch.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {


// The bands a spectral camera's exit-pupil bounds are measured for, over the visible range it
// traces (that of the spectral film): narrower where glasses disperse most.
const std::vector<double> kPupilBandEdgesNm = {360, 410, 460, 520, 590, 680, 830};

// A film point's distance from the axis. Film coordinates are millimetres under 10^4: no overflow,
// and the square root costs a fraction of std::hypot's on every camera ray.
double filmRadius(double x, double y) { return std::sqrt(x * x + y * y); }

}  // namespace

RealisticParams realisticParams(const std::string& lensPath, std::optional<double> fstop, double focusDistanceMm) {
    RealisticParams p;
    p.lensPath = lensPath;
    p.lens = loadLensSystem(lensPath);
    if (fstop) p.settings.fstop = Setting{*fstop, "fstop"};
    p.settings.focusDistance = Setting{focusDistanceMm, "focus distance"};
    return p;
}

RealisticCamera::RealisticCamera(const RealisticParams& params, const Transform& cameraToWorld, int width, int height,
                                 double filmMarginPixels, const std::atomic<bool>* cancel,
                                 const std::function<void(double)>& progress)
    : params_(params), cameraToWorld_(cameraToWorld), width_(width), height_(height) {
    if (!(params.filmDiagonalMm > 0 && params.filmDiagonalMm < 1e4))
        throw OpticsError("film diagonal must lie in (0, 10000) mm, got " + formatNumber(params.filmDiagonalMm));
    if (!(params.exposureTime > 0)) throw OpticsError("exposure time (shutterclose) must be positive");
    if (!(params.cameraUnitMm > 0)) throw OpticsError("the camera unit must be a positive number of millimetres");
    if (!(params.autoThresholdPixels > 0)) throw OpticsError("the auto threshold must be a positive number of pixels");
    const double diag = std::hypot(double(width), double(height));
    halfWidthMm_ = 0.5 * params.filmDiagonalMm * width / diag;
    halfHeightMm_ = 0.5 * params.filmDiagonalMm * height / diag;
    const double fullFrameRadius = findFilmRadiusRange(filmMarginPixels);

    LensSettings settings = params.settings;
    settings.focusModel = params.mode == LensMode::Thick ? FocusModel::Thick : FocusModel::Exact;
    analysis_ = analyzeLens(params.lens, settings);
    filmZExact_ = analysis_.focus.imageZExact;
    filmZThick_ = analysis_.focus.imageZThick;
    originZ_ = params.originAtFilm ? filmZ() : 0;
    mounted_ = params.mount.isMoved();
    if (mounted_) {
        if (params.spectral) throw OpticsError("a tilted or shifted lens renders in RGB at one wavelength: turn spectral off");
        if (params.ghosts.on()) throw OpticsError("lens flare is not modelled for a tilted or shifted lens: turn ghosts off");
        bodyFromLens_ = bodyFromLens(params.mount, analysis_.firstOrder.zPPrime);
        lensFromBody_ = bodyFromLens_.inverse();
    }

    const double pixelMm = params.filmDiagonalMm / diag;
    switch (params.mode) {
        case LensMode::Exact: modes_ = LensModeMap::exactEverywhere(minFilmRadius_, maxFilmRadius_); break;
        case LensMode::Thick: modes_ = LensModeMap::thickEverywhere(minFilmRadius_, maxFilmRadius_); break;
        case LensMode::Auto:
            if (mounted_) {
                modes_ = LensModeMap::exactEverywhere(minFilmRadius_, maxFilmRadius_);
                break;
            }
            errors_ = measureThickLensFilmError(analysis_, minFilmRadius_, maxFilmRadius_);
            modes_ = LensModeMap::fromErrors(errors_, params.autoThresholdPixels * pixelMm);
            thickShare_ = thickShareOfCrop();
            if (modes_.usesExact() && thickShare_ < kAutoMinThickShare)
                modes_ = LensModeMap::exactEverywhere(minFilmRadius_, maxFilmRadius_);
            break;
    }
    const auto checkFilm = [&](double z) {
        if (!(z < analysis_.lens.rearZ()))
            throw OpticsError("the film would sit at z = " + formatNumber(z) + " mm, in front of the rear vertex");
    };
    if (modes_.usesThick()) {
        checkFilm(filmZThick_);
        const Pupil& xp = analysis_.pupils.exit;
        if (mounted_) {
            film_ = mountedFilm(filmZThick_);
            for (const double sx : {-1.0, 1.0})
                for (const double sy : {-1.0, 1.0})
                    if (!(xp.z > film_.at(sx * (halfWidthMm_ + filmMarginMm_), sy * (halfHeightMm_ + filmMarginMm_)).z))
                        throw OpticsError("the exit pupil lies behind a corner of the tilted film; the thick-lens model cannot aim at it");
        }
        if (!(xp.z > filmZThick_)) throw OpticsError("the exit pupil lies behind the film; the thick-lens model cannot aim at it");
        const double dz = xp.z - filmZThick_;
        const double centreWeight = M_PI * 0.25 * xp.diameter * xp.diameter / (dz * dz);
        weightScaleThick_ = params.simpleWeighting ? (centreWeight > 0 ? 1.0 / centreWeight : 0.0) : params.exposureTime;
    }
    if (modes_.usesExact()) {
        checkFilm(filmZExact_);
        // The whole frame's radii (64 over the disc), only those around the radii traced exactly: a
        // crop's regions are then the whole frame's, and so are its pixels.
        const double step = fullFrameRadius / (ExitPupilBoundsOptions{}.filmRadii - 1);
        const double slack = 1e-9;  // a radius on a measured one must not pull in the next
        const int first = int(std::floor(modes_.exactMinRadius() / step + slack));
        const int last = std::max(first + 1, int(std::ceil(modes_.exactMaxRadius() / step - slack)));
        ExitPupilBoundsOptions measure;
        measure.cancel = cancel;
        measure.progress = progress;
        if (params.spectral) {
            etas_ = tabulateEtas(analysis_.lens, TraceDirection::FilmToScene, kVisibleFirstNm, kVisibleLastNm);
            etasBack_ = tabulateEtas(analysis_.lens, TraceDirection::SceneToFilm, kVisibleFirstNm, kVisibleLastNm);
            if (!params.aperture.isCircular())
                for (int k = 0; k < etas_.bands; ++k) bandLenses_.push_back(atWavelength(analysis_.lens, etas_.bandCentreNm(k)));
        }
        if (mounted_) {
            film_ = mountedFilm(filmZExact_);
            // Aimed through the exit pupil's plane where it lies in front of the film (FilmPlanePupilBounds.h).
            const double halfU = halfWidthMm_ + filmMarginMm_, halfV = halfHeightMm_ + filmMarginMm_;
            const Pupil& xp = analysis_.pupils.exit;
            double nearest = -std::numeric_limits<double>::infinity();
            for (const double su : {-1.0, 1.0})
                for (const double sv : {-1.0, 1.0}) nearest = std::max(nearest, film_.at(su * halfU, sv * halfV).z);
            const bool throughPupil = std::isfinite(xp.z) && xp.z > nearest + 1e-3 && xp.diameter > 0;
            filmBounds_ = computeFilmPlanePupilBounds(analysis_.lens, film_, halfU, halfV,
                                                      throughPupil ? xp.z : analysis_.lens.rearZ(),
                                                      throughPupil ? 0.5 * xp.diameter : analysis_.lens.surfaces.back().apertureRadius);
        } else if (params.spectral) {
            spectralBounds_ = computeSpectralExitPupilBounds(analysis_.lens, filmZExact_, step, first, last,
                                                             kPupilBandEdgesNm, measure);
            bounds_ = spectralBounds_.at(analysis_.lens.wavelength);
        } else {
            bounds_ = computeExitPupilBounds(analysis_.lens, filmZExact_, step, first, last, measure);
        }
        if (!mounted_) imageCircleRadiusMm_ = imageCircleRadius(analysis_.lens, filmZExact_, 0.5 * params.filmDiagonalMm);
        const double centreWeight = params.simpleWeighting ? exactCentreWeight() : 0;
        weightScaleExact_ = params.simpleWeighting ? (centreWeight > 0 ? 1.0 / centreWeight : 0.0) : params.exposureTime;
    }
    if (params.simpleWeighting && params.pbrtExposure) {
        // pbrt-v3's exposure: film-to-rear-vertex distance squared over its first pupil box's area.
        const double boxArea = pbrtFirstPupilBoxArea(analysis_.lens, filmZ(), params.filmDiagonalMm);
        const double d = analysis_.lens.rearZ() - filmZ();
        weightScaleExact_ = weightScaleThick_ = boxArea > 0 ? d * d / boxArea : 0.0;
    }
}

std::optional<FilmRadiometry> RealisticCamera::filmRadiometry() const {
    const double scale = modes_.usesExact() ? weightScaleExact_ : weightScaleThick_;
    if (!(scale > 0)) return std::nullopt;
    return FilmRadiometry{params_.exposureTime / scale, params_.exposureTime, params_.filmDiagonalMm};
}

double RealisticCamera::findFilmRadiusRange(double filmMarginPixels) {
    // The crop window in pixels (pbrt-v3's rounding), widened by the pixel filter's reach.
    const std::array<double, 4>& c = params_.crop;
    if (!(c[0] >= 0 && c[0] < c[1] && c[1] <= 1 && c[2] >= 0 && c[2] < c[3] && c[3] <= 1))
        throw OpticsError("crop window x0,x1,y0,y1 must satisfy 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1");
    const double reach = filmMarginPixels + 1;
    const auto span = [&](double a, double b, int pixels, double halfMm, double& nearMm, double& farMm) {
        const double lo = (std::ceil(pixels * a) - reach) / pixels, hi = (std::ceil(pixels * b) + reach) / pixels;
        const double mmLo = (2 * lo - 1) * halfMm, mmHi = (2 * hi - 1) * halfMm;  // film axis, up to sign
        nearMm = mmLo <= 0 && mmHi >= 0 ? 0.0 : std::min(std::fabs(mmLo), std::fabs(mmHi));
        farMm = std::max(std::fabs(mmLo), std::fabs(mmHi));
    };
    double nearX, farX, nearY, farY;
    span(c[0], c[1], width_, halfWidthMm_, nearX, farX);
    span(c[2], c[3], height_, halfHeightMm_, nearY, farY);
    minFilmRadius_ = std::hypot(nearX, nearY);
    maxFilmRadius_ = std::hypot(farX, farY);
    filmMarginMm_ = 2 * reach / width_ * halfWidthMm_;
    return std::hypot(halfWidthMm_ + filmMarginMm_, halfHeightMm_ + filmMarginMm_);
}

double RealisticCamera::thickShareOfCrop() const {
    constexpr int kGrid = 64;  // points across the crop window each way
    const std::array<double, 4>& c = params_.crop;
    int thick = 0;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            double fx, fy;
            filmPoint((c[0] + (c[1] - c[0]) * (i + 0.5) / kGrid) * width_, (c[2] + (c[3] - c[2]) * (j + 0.5) / kGrid) * height_,
                      fx, fy);
            thick += modes_.thickAt(filmRadius(fx, fy));
        }
    return double(thick) / (kGrid * kGrid);
}

double RealisticCamera::exactCentreWeight() const {
    if (mounted_) {
        const PupilCircle c = filmPlanePupilCircle(filmBounds_, 0, 0);
        const double dz = filmBounds_.aimZ - film_.origin.z;
        return M_PI * c.radius * c.radius / (dz * dz);
    }
    // The film centre's region, measured apart when the crop leaves the centre out, or at the lens's
    // own wavelength alone when the bounds are a spectral band's (the exposure stays the RGB film's).
    const ExitPupilBounds centre = bounds_.firstRadius == 0 && !params_.spectral
                                       ? bounds_
                                       : computeExitPupilBounds(analysis_.lens, filmZExact_, bounds_.radiusStep, 0, 1);
    const double dz = centre.aimZ - filmZExact_;
    return sampleExitPupil(centre, 0, 0, 0.5, 0.5).area / (dz * dz);
}

double RealisticCamera::filmZ() const { return params_.mode == LensMode::Thick ? filmZThick_ : filmZExact_; }

void RealisticCamera::filmPoint(double rasterX, double rasterY, double& x, double& y) const {
    const double sx = 2.0 * rasterX / width_ - 1.0;   // -1 left, +1 right
    const double sy = 1.0 - 2.0 * rasterY / height_;  // +1 top, -1 bottom
    x = -sx * halfWidthMm_;
    y = -sy * halfHeightMm_;
}

void RealisticCamera::rasterPoint(double x, double y, double& rasterX, double& rasterY) const {
    rasterX = 0.5 * width_ * (1.0 - x / halfWidthMm_);
    rasterY = 0.5 * height_ * (1.0 + y / halfHeightMm_);
}

// Irradiance from a patch dA of the exit pupil's plane: L cos(film) cos(pupil) / dist^2 dA (with
// the film square to the axis, L cos^4 / dz^2 dA).
double RealisticCamera::aimThick(const Vec3& from, const Vec3& normal, float u1, float u2, Ray& ray) const {
    float dx, dy;
    concentricDisk(u1, u2, dx, dy);
    const Pupil& xp = analysis_.pupils.exit;
    // The exit pupil is the stop's image: a pupil point maps back to the stop by the sign of its
    // magnification.
    const double toStop = xp.magnification < 0 ? -1.0 : 1.0;
    const double shape = params_.aperture.weight(toStop * dx, toStop * dy);
    if (!(shape > 0)) return 0;
    const Vec3 d = Vec3{0.5 * xp.diameter * dx, 0.5 * xp.diameter * dy, xp.z} - from;
    const double dist2 = dot(d, d);
    ray = {from, (1.0 / std::sqrt(dist2)) * d};
    return shape * dot(ray.direction, normal) * ray.direction.z * (M_PI * 0.25 * xp.diameter * xp.diameter) / dist2 *
           weightScaleThick_;
}

TraceResult RealisticCamera::traceShaped(const LensSystem& lens, const Ray& ray, TraceDirection direction,
                                         double& weight) const {
    if (params_.aperture.isCircular()) return traceRay(lens, ray, direction);
    // To the stop (the stop included), the shape where the ray crosses it, then on through the rest.
    const int stop = lens.stopIndex;
    const bool fromFilm = direction == TraceDirection::FilmToScene;
    TraceOptions toStop, beyond;
    (fromFilm ? toStop.begin : toStop.end) = fromFilm ? stop : stop + 1;
    (fromFilm ? beyond.end : beyond.begin) = fromFilm ? stop : stop + 1;
    const TraceResult atStop = traceRay(lens, ray, direction, toStop);
    if (!atStop.ok()) return atStop;
    const double radius = lens.stop().apertureRadius;
    weight *= params_.aperture.weight(atStop.ray.origin.x / radius, atStop.ray.origin.y / radius);
    return traceRay(lens, atStop.ray, direction, beyond);
}

bool RealisticCamera::finish(const Ray& leaving, double weight, CameraRay& out) const {
    // A moved lens's rays leave it in its own coordinates; camera space is the body's.
    Ray moved;
    if (mounted_) moved = movedRay(bodyFromLens_, leaving);
    const Ray& lensRay = mounted_ ? moved : leaving;
    const double unit = 1.0 / params_.cameraUnitMm;
    const Vec3f o{float(lensRay.origin.x * unit), float(lensRay.origin.y * unit), float((lensRay.origin.z - originZ_) * unit)};
    const Vec3f dir{float(lensRay.direction.x), float(lensRay.direction.y), float(lensRay.direction.z)};
    out.origin = transformPoint(cameraToWorld_, o);
    out.direction = normalize(transformVector(cameraToWorld_, dir));
    out.weight = float(weight);
    if (!std::isfinite(out.weight)) out.weight = 0;
    return out.weight > 0;
}

bool RealisticCamera::generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const {
    double fx, fy;
    filmPoint(rasterX, rasterY, fx, fy);
    if (mounted_ || !modes_.thickAt(filmRadius(fx, fy))) {
        // One exact ray is a batch of one: the same bits as the renderer's batches.
        const CameraSample sample{rasterX, rasterY, u1, u2};
        generateRays(&sample, 1, &out);
        return out.weight > 0;
    }
    Ray ray;
    const double weight = aimThick({fx, fy, filmZThick_}, {0, 0, 1}, u1, u2, ray);
    const TraceResult r = traceThick(analysis_.thick, ray, TraceDirection::FilmToScene);
    return weight > 0 && r.ok() && finish(r.ray, weight, out);
}

void RealisticCamera::generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const {
    thread_local ExactRayBatch b;
    makeRays(samples, n, out, b);
}

void RealisticCamera::makeRays(const CameraSample* samples, std::size_t n, CameraRay* out, ExactRayBatch& b) const {
    b.sampleOf.clear();
    if (mounted_) {
        makeMountedRays(samples, n, out, b);
        return;
    }
    if (!modes_.usesExact()) {
        Camera::generateRays(samples, n, out);
        return;
    }
    // Thick-lens samples are made one by one; the exact ones together, each stage one loop over
    // them in structure-of-arrays form so that it vectorises.
    b.filmX.resize(n);
    b.filmY.resize(n);
    b.u1.resize(n);
    b.u2.resize(n);
    b.sampleOf.resize(n);
    b.bands.resize(n);
    b.nm.resize(n);
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const CameraSample& s = samples[i];
        double fx, fy;
        filmPoint(s.rasterX, s.rasterY, fx, fy);
        if (modes_.thickAt(filmRadius(fx, fy))) {
            if (!generateRay(s.rasterX, s.rasterY, s.u1, s.u2, out[i])) out[i].weight = 0;
            continue;
        }
        b.filmX[m] = fx;
        b.filmY[m] = fy;
        b.u1[m] = s.u1;
        b.u2[m] = s.u2;
        if (params_.spectral) {
            b.nm[m] = s.wavelengthNm > 0 ? s.wavelengthNm : analysis_.lens.wavelength;
            b.bands[m] = etas_.band(b.nm[m]);
        }
        b.sampleOf[m++] = i;
    }
    b.sampleOf.resize(m);
    if (m == 0) return;
    if (params_.spectral)
        sampleSpectralExitPupils(spectralBounds_, m, b.filmX.data(), b.filmY.data(), b.u1.data(), b.u2.data(), b.nm.data(),
                                 b.pupil);
    else
        sampleExitPupils(bounds_, m, b.filmX.data(), b.filmY.data(), b.u1.data(), b.u2.data(), b.pupil);
    b.rays.resize(m);
    b.weights.resize(m);
    aimExactRays(m, b);
    traceAimedRays(m, b, out);
}

void RealisticCamera::traceAimedRays(std::size_t m, ExactRayBatch& b, CameraRay* out) const {
    if (params_.aperture.isCircular()) {
        if (params_.spectral) traceBatch(analysis_.lens, b.rays, TraceDirection::FilmToScene, etas_, b.bands.data());
        else traceBatch(analysis_.lens, b.rays, TraceDirection::FilmToScene);
    }
    for (std::size_t k = 0; k < m; ++k) {
        CameraRay& o = out[b.sampleOf[k]];
        o.weight = 0;
        if (!(b.weights[k] > 0)) continue;
        if (params_.aperture.isCircular()) {
            if (b.rays.blocked[k] == BlockReason::None) finish(b.rays.get(k), b.weights[k], o);
            continue;
        }
        double weight = b.weights[k];  // a shaped stop is met ray by ray
        const LensSystem& lens = params_.spectral ? bandLenses_[b.bands[k]] : analysis_.lens;
        const TraceResult r = traceShaped(lens, b.rays.get(k), TraceDirection::FilmToScene, weight);
        if (r.ok() && weight > 0) finish(r.ray, weight, o);
        b.rays.set(k, r.ray);
        b.rays.blocked[k] = r.ok() && weight > 0 ? BlockReason::None : BlockReason::ClippedByStop;
    }
}

void RealisticCamera::makeMountedRays(const CameraSample* samples, std::size_t n, CameraRay* out, ExactRayBatch& b) const {
    const Vec3 normal = film_.normal();
    if (!modes_.usesExact()) {
        for (std::size_t i = 0; i < n; ++i) {
            double fx, fy;
            filmPoint(samples[i].rasterX, samples[i].rasterY, fx, fy);
            Ray ray;
            const double weight = aimThick(film_.at(fx, fy), normal, samples[i].u1, samples[i].u2, ray);
            const TraceResult r = traceThick(analysis_.thick, ray, TraceDirection::FilmToScene);
            out[i].weight = 0;
            if (weight > 0 && r.ok()) finish(r.ray, weight, out[i]);
        }
        return;
    }
    // Each film point aims at a uniform point of its circle on the aiming plane (FilmPlanePupilBounds):
    // irradiance L cos(film) cos(aim) / dist^2 dA.
    b.sampleOf.resize(n);
    b.rays.resize(n);
    b.weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        double fx, fy;
        filmPoint(samples[i].rasterX, samples[i].rasterY, fx, fy);
        const Vec3 from = film_.at(fx, fy);
        const PupilCircle c = filmPlanePupilCircle(filmBounds_, fx, fy);
        float dx, dy;
        concentricDisk(samples[i].u1, samples[i].u2, dx, dy);
        const Vec3 d = Vec3{c.x + c.radius * dx, c.y + c.radius * dy, filmBounds_.aimZ} - from;
        const double dist2 = dot(d, d);
        const Ray ray{from, (1.0 / std::sqrt(dist2)) * d};
        b.sampleOf[i] = i;
        b.rays.set(i, ray);
        b.weights[i] = c.radius > 0 ? dot(ray.direction, normal) * ray.direction.z * M_PI * c.radius * c.radius / dist2 *
                                          weightScaleExact_
                                    : 0.0;
    }
    traceAimedRays(n, b, out);
}

FilmPlane RealisticCamera::mountedFilm(double filmZ) const {
    // The film's centre and its x and y axes, carried into lens space as two rays from the centre.
    const Ray u = movedRay(lensFromBody_, {{0, 0, filmZ}, {1, 0, 0}});
    return {u.origin, u.direction, movedRay(lensFromBody_, {{0, 0, filmZ}, {0, 1, 0}}).direction};
}

// Irradiance from a patch dA of the aiming plane: L cos^2 / dist^2 dA = L cos^4 / dz^2 dA.
void RealisticCamera::aimExactRays(std::size_t count, ExactRayBatch& b) const {
    const double z = filmZExact_, aimZ = bounds_.aimZ, scale = weightScaleExact_;
    const double* px = b.pupil.x.data();
    const double* py = b.pupil.y.data();
    const double* area = b.pupil.area.data();
    RayBatch& r = b.rays;
#pragma GCC ivdep
    for (std::size_t k = 0; k < count; ++k) {
        const double dx = px[k] - b.filmX[k], dy = py[k] - b.filmY[k], dz = aimZ - z;
        const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz);
        r.ox[k] = b.filmX[k];
        r.oy[k] = b.filmY[k];
        r.oz[k] = z;
        r.dx[k] = inv * dx;
        r.dy[k] = inv * dy;
        r.dz[k] = inv * dz;
        b.weights[k] = area[k] > 0 ? cos4(r.dz[k]) * area[k] / (dz * dz) * scale : 0.0;
    }
}

std::vector<std::string> RealisticCamera::warnings() const {
    const double filmRadius = 0.5 * params_.filmDiagonalMm;
    // A circle that reaches the corner (the bisection stops just short of it) is no shortfall; none
    // from the centre is left to the render's count of blocked rays, which measures it.
    if (!imageCircleRadiusMm_ || *imageCircleRadiusMm_ == 0 || *imageCircleRadiusMm_ >= filmRadius * (1 - 1e-6)) return {};
    return {"the lens's image circle (" + formatFixed(2 * *imageCircleRadiusMm_, 2) + " mm across on the film) is smaller than the film (" +
            formatFixed(params_.filmDiagonalMm, 2) + " mm diagonal): beyond it the frame is black"};
}

std::map<std::string, std::string> RealisticCamera::describe() const {
    const LensAnalysis& a = analysis_;
    std::map<std::string, std::string> d{{"camera", "realistic"},
            {"lensFile", params_.lensPath},
            {"lensName", a.lens.name},
            {"mode", lensModeName(params_.mode)},
            {"lensModelByFilmRadius", modes_.describe()},
            {"renderedFilmRadiiMm", formatNumber(minFilmRadius_) + " to " + formatNumber(maxFilmRadius_)},
            {"exitPupilBoundsRadii", std::to_string(bounds_.radiusCount())},
            {"fstop", formatNumber(a.fstop)},
            {"stopDiameterMm", formatNumber(a.stopDiameter)},
            {"focusDistanceMm", a.focus.infinity ? "inf" : formatNumber(a.focus.objectZ - a.lens.frontZ())},
            {"filmPlacement", params_.settings.filmDistance ? "filmdistance " + formatNumber(params_.settings.filmDistance->value) + " mm behind the rear vertex"
                                                     : "focused"},
            {"aperture", params_.aperture.name()},
            {"filmDiagonalMm", formatNumber(params_.filmDiagonalMm)},
            {"imageCircleDiameterMm", imageCircleRadiusMm_ ? formatNumber(2 * *imageCircleRadiusMm_) : "not measured (no exact trace, or a moved lens)"},
            {"filmZMm", formatNumber(filmZ())},
            {"eflMm", formatNumber(a.firstOrder.efl)},
            {"exitPupilZMm", formatNumber(a.pupils.exit.z)},
            {"exitPupilDiameterMm", formatNumber(a.pupils.exit.diameter)},
            {"exposureTimeS", formatNumber(params_.exposureTime)},
            {"weighting", !params_.simpleWeighting ? "radiometric (cos^4 A / d^2 * t)"
                          : params_.pbrtExposure ? "simple, pbrt-v3's exposure (d^2 / first pupil box)"
                                                 : "simple (centre = 1)"},
            {"cameraSpaceUnitMm", formatNumber(params_.cameraUnitMm)},
            {"cameraSpaceOrigin", params_.originAtFilm ? "film" : "front vertex"},
            {"lensWavelengths", params_.spectral ? "each exact ray at its sample's wavelengths, 360-830 nm in 1 nm bands"
                                                 : formatNumber(a.lens.wavelength) + " nm"}};
    if (mounted_) {
        const LensMount& m = params_.mount;
        d["lensTiltDeg"] = formatNumber(m.tiltDegrees);
        d["lensSwingDeg"] = formatNumber(m.swingDegrees);
        d["lensShiftMm"] = formatNumber(m.shiftMm[0]) + ", " + formatNumber(m.shiftMm[1]);
        d["lensPivot"] = "rear principal point, z = " + formatNumber(a.firstOrder.zPPrime) + " mm";
        d["exitPupilBoundsGrid"] = std::to_string(filmBounds_.nodesU) + " x " + std::to_string(filmBounds_.nodesV) + " film points";
    }
    if (params_.mode == LensMode::Auto && !mounted_) {
        // The prediction behind the split, per radius: the thick lens's worst film error in pixels
        // and its brightness against the exact lens's; and the share of the film it was allowed.
        const double pixelMm = params_.filmDiagonalMm / std::hypot(double(width_), double(height_));
        std::string errors, brightness;
        for (const ThickLensFilmError& e : errors_) {
            errors += (errors.empty() ? "" : ", ") + formatNumber(e.filmRadius) + " mm: " + formatNumber(e.maxErrorMm / pixelMm);
            brightness += (brightness.empty() ? "" : ", ") + formatNumber(e.filmRadius) + " mm: " +
                          formatNumber(e.illuminationRatio, 3);
        }
        d["autoThresholdPixels"] = formatNumber(params_.autoThresholdPixels);
        d["thickLensErrorPixels"] = errors;
        d["thickLensBrightnessRatio"] = brightness;
        d["thickLensShareOfFilm"] = formatNumber(thickShare_, 3);
    }
    return d;
}

}  // namespace lenslab
