#pragma once
// The realistic camera of Kolb, Mitchell & Hanrahan (1995): rays from the film through a real lens
// (exact trace, "exact"), its thick-lens model ("thick"), or each by film radius ("auto": the
// thick lens where its predicted position and brightness errors stay under the thresholds, see
// LensModeMap.h). Lens space is millimetres with the origin at the front vertex and +z toward the
// scene, like pbrt's camera space; a lens-space ray leaving the front element maps to camera space
// by dividing by the millimetres of one camera unit (1 with the course's parameters, whose camera
// space is millimetres; 1000 with pbrt-v3's lensfile, whose camera space is metres:
// docs/camera-conventions.md).
//
// Each model keeps its own film plane (exact: best focus of the real lens; thick: the thick-lens
// conjugate of the plane of focus), so an auto picture equals the accurate one where the exact
// trace is used and the approximate one elsewhere, sample for sample.
#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cameras/ApertureShape.h"
#include "cameras/Camera.h"
#include "cameras/GhostSelection.h"
#include "cameras/LensMount.h"
#include "trace/ExactTrace.h"
#include "firstorder/ExitPupilBounds.h"
#include "firstorder/FilmPlanePupilBounds.h"
#include "settings/LensAnalysis.h"
#include "settings/LensSettings.h"
#include "cameras/LensModeMap.h"
#include "trace/RayBatch.h"
#include "trace/WavelengthEtas.h"
#include "core/Transform.h"

namespace lenslab {

struct RealisticParams {
    std::string lensPath;                  // for the metadata
    LensSystem lens;                       // the table as read, in its checked layout
    LensSettings settings;                 // aperture and focus, checked by analyzeLens
    double cameraUnitMm = 1000;            // millimetres per camera-space unit (1: course, 1000: pbrt-v3)
    // Where camera space's origin lies: the course puts the front lens vertex there, pbrt-v3 the film.
    bool originAtFilm = false;
    ApertureShape aperture;                // pbrt-v4's shape of the stop's opening
    double filmDiagonalMm = 35;
    LensMode mode = LensMode::Exact;
    double autoThresholdPixels = 0.5;      // auto: the largest predicted thick-lens film error allowed
    // The rendered part of the image, x0, x1, y0, y1 as fractions (pbrt's cropwindow): only the film
    // radii it reaches are prepared (error map, exit-pupil bounds).
    std::array<double, 4> crop = {0, 1, 0, 1};
    double exposureTime = 1;               // seconds the shutter is open (> 0)
    bool simpleWeighting = false;          // pbrt-v3: weights normalised to 1 at the image centre
    // With simpleWeighting: pbrt-v3's exposure (optics/firstorder/PbrtPupilBox.h) instead of the centre at 1.
    bool pbrtExposure = false;
    // Trace each exact ray at its sample's wavelength (CameraSample::wavelengthNm), with the lens's
    // dispersion; the thick lens stays at the lens's wavelength. Only for a dispersive lens.
    bool spectral = false;
    GhostSelection ghosts;                 // lens flare (cameras/LensFlare.h), made by the frame
    // A tilt and shift of the lens against the body and film (LensMount.h). A moved lens is traced
    // exactly (auto is exact everywhere: its error map assumes a film square to the axis) or as the
    // thick lens, in RGB without ghosts, and aims at FilmPlanePupilBounds.
    LensMount mount;
};

// Parameters for a lens file at an f-number (nullopt: the widest) focused at focusDistanceMm from the
// front vertex: the benchmarks' and tests' shorthand.
RealisticParams realisticParams(const std::string& lensPath, std::optional<double> fstop, double focusDistanceMm);

class RealisticCamera : public Camera {
public:
    // Throws OpticsError (range violations name the range) and LensTableError.
    // filmMarginPixels: how far beyond the image the pixel filter reaches. cancel and progress
    // reach the exit-pupil measurement, the bulk of the setup: a set cancel throws SetupCancelled.
    RealisticCamera(const RealisticParams& params, const Transform& cameraToWorld, int width, int height,
                    double filmMarginPixels, const std::atomic<bool>* cancel = nullptr,
                    const std::function<void(double)>& progress = {});
    bool generateRay(double rasterX, double rasterY, float u1, float u2, CameraRay& out) const override;
    void generateRays(const CameraSample* samples, std::size_t n, CameraRay* out) const override;
    // Each ray made at its sample's own wavelength, then traced back through the lens at the others
    // (WavelengthLandings.cpp).
    void generateSpectralRays(const CameraSample* samples, std::size_t n, const double* wavelengthsNm, int perSample,
                              CameraRay* out, FilmLanding* landings) const override;
    std::map<std::string, std::string> describe() const override;
    std::vector<std::string> warnings() const override;
    bool spectral() const override { return params_.spectral; }
    // The exposure per value is the exposure time over the weight scale of the model the film is
    // rendered with (the exact trace's where it traces any ray exactly): each normalises its own.
    std::optional<FilmRadiometry> filmRadiometry() const override;

    const LensAnalysis& analysis() const { return analysis_; }
    double filmZ() const;  // mm, lens space: the thick-lens film in approximate mode, else the exact one
    const ExitPupilBounds& pupilBounds() const { return bounds_; }  // radiusCount() 0 when unused
    const LensModeMap& lensModes() const { return modes_; }
    // Auto mode: the predicted thick-lens error over the rendered film radii (empty otherwise).
    const std::vector<ThickLensFilmError>& thickLensErrors() const { return errors_; }
    // mm on the exact film: the largest film radius from which some ray passes the lens, up to the
    // film's corner; none where the lens is not traced exactly or is moved (tilt-shift).
    std::optional<double> imageCircleRadiusMm() const { return imageCircleRadiusMm_; }
    double minFilmRadius() const { return minFilmRadius_; }  // mm: the film radii rays can start from
    double maxFilmRadius() const { return maxFilmRadius_; }
    // The film point (mm, lens space z = filmZ) a raster position maps to; the lens inverts the
    // image, so the top-left pixel sits at +x, -y (pbrt's camera x points right, y up).
    void filmPoint(double rasterX, double rasterY, double& x, double& y) const;
    void rasterPoint(double x, double y, double& rasterX, double& rasterY) const;  // filmPoint's inverse
    // What lens flare (cameras/LensFlare.h) needs: the parameters, where the camera stands, and the
    // factor the exact trace's weights carry on irradiance (exposure time, or simple weighting's).
    const RealisticParams& params() const { return params_; }
    const Transform& cameraToWorld() const { return cameraToWorld_; }
    double exactWeightScale() const { return weightScaleExact_; }
    double lensSpaceOriginZ() const { return originZ_; }  // mm: camera space's origin in lens space

private:
    // Sets the film radii the crop window reaches; returns the whole frame's reach.
    double findFilmRadiusRange(double filmMarginPixels);
    double exactCentreWeight() const;
    // Auto: the fraction of the crop window's film area where the thick lens is allowed.
    double thickShareOfCrop() const;
    // Where a thick-lens ray from the film point `from` (lens space; the film's normal toward the
    // lens `normal`) is aimed and the weight it will carry if the lens passes it (0: no aim).
    double aimThick(const Vec3& from, const Vec3& normal, float u1, float u2, Ray& ray) const;
    // The exact rays of a batch: film points and lens samples in, pupil points, rays and weights
    // (0: no aim) out, as structure of arrays.
    struct ExactRayBatch {
        std::vector<double> filmX, filmY, u1, u2;
        std::vector<std::size_t> sampleOf;  // the caller's index of each exact sample
        std::vector<std::uint16_t> bands;   // spectral: each ray's wavelength band
        std::vector<double> nm;             // spectral: each ray's wavelength
        PupilSampleBatch pupil;
        RayBatch rays;
        std::vector<double> weights;
    };
    void aimExactRays(std::size_t count, ExactRayBatch& batch) const;
    // generateRays, leaving the exact samples' batch in b (its rays in lens space, in front of the lens).
    void makeRays(const CameraSample* samples, std::size_t n, CameraRay* out, ExactRayBatch& b) const;
    // makeRays for a moved lens (params.mount): every sample aimed from its point of the film plane.
    void makeMountedRays(const CameraSample* samples, std::size_t n, CameraRay* out, ExactRayBatch& b) const;
    // The batch's first m rays, aimed and weighted, traced through the lens and finished into out.
    void traceAimedRays(std::size_t m, ExactRayBatch& b, CameraRay* out) const;
    // A moved lens: its film plane in lens space, the plane body z = filmZ.
    FilmPlane mountedFilm(double filmZ) const;
    // The landings of the batch's rays that passed, at the sample's wavelengths beyond its own.
    void landOtherWavelengths(const ExactRayBatch& b, const double* wavelengthsNm, int perSample,
                              FilmLanding* landings) const;
    // The exact trace through `lens` with the stop's shape applied where the ray crosses the stop;
    // the weight is multiplied by the shape's.
    TraceResult traceShaped(const LensSystem& lens, const Ray& ray, TraceDirection direction, double& weight) const;
    bool finish(const Ray& lensRay, double weight, CameraRay& out) const;

    RealisticParams params_;
    Transform cameraToWorld_;
    int width_, height_;
    double halfWidthMm_, halfHeightMm_;
    double filmMarginMm_ = 0;        // how far the pixel filter reaches beyond the image
    double minFilmRadius_ = 0, maxFilmRadius_ = 0;
    LensAnalysis analysis_;
    double filmZExact_ = 0, filmZThick_ = 0;
    double originZ_ = 0;             // mm, lens space: camera space's origin (front vertex or film)
    std::vector<ThickLensFilmError> errors_;
    LensModeMap modes_;
    double thickShare_ = 0;          // auto: thickShareOfCrop() of the allowed bands
    std::optional<double> imageCircleRadiusMm_;
    ExitPupilBounds bounds_;         // for the exact trace's film radii (spectral: its own wavelength's band)
    SpectralExitPupilBounds spectralBounds_;  // spectral: per band of wavelengths
    WavelengthEtas etas_;            // spectral: the lens's index ratios per 1 nm band
    WavelengthEtas etasBack_;        // the same for tracing from the scene back to the film
    std::vector<LensSystem> bandLenses_;  // spectral with a shaped stop: the lens at each band
    // Exposure time, or 1 / centre weight for simple weighting (each model normalised by its own).
    double weightScaleExact_ = 1, weightScaleThick_ = 1;
    // A moved lens (params.mount): lens space to the body's coordinates and back, the film plane of
    // the model in use in lens space, and the exact trace's bounds over it.
    bool mounted_ = false;
    RigidMotion bodyFromLens_, lensFromBody_;
    FilmPlane film_;
    FilmPlanePupilBounds filmBounds_;
};

}  // namespace lenslab
