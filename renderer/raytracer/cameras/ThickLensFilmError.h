#pragma once
// How far the approximate camera's picture lies from the accurate one's, per film radius.
//
// The accurate camera puts the film where the exact lens focuses best (imageZExact) and traces the
// real lens; the approximate one puts it at the thick-lens conjugate (imageZThick) and traces the
// thick lens, which images that film point onto ONE point of the plane of focus. So each exact ray
// from the film point (r, 0) is compared with that point where it crosses the plane of focus; the
// difference divided by the lateral magnification is the error as the film sees it (mm). It holds
// distortion (where the pixel looks) and aberration blur (how far its rays stray). Focus at infinity
// uses a plane a million focal lengths away, where the same division gives angle times focal length.
//
// Millimetres, lens space (origin at the front vertex, +z toward the scene, film at negative z).
#include <vector>

#include "settings/LensAnalysis.h"

namespace lenslab {

struct ThickLensFilmError {
    double filmRadius = 0;          // mm
    double maxErrorMm = 0;          // the worst exact ray (infinity when no exact ray passes)
    double centroidErrorMm = 0;     // mean exact landing against the thick image point: distortion
    double directionErrorRad = 0;   // mean exact direction against the thick chief ray's
    double illuminationRatio = 0;   // thick-lens film irradiance / exact (1 = same brightness)
    int exactRays = 0;              // exact rays that passed the lens (of a half-grid over the pupil)
};

struct ThickLensFilmErrorOptions {
    int filmRadii = 12;  // sampled evenly from the minimum to the maximum radius
    // Grid cells across the passing rays' box on the aiming plane (its y >= 0 half): at 64 the
    // brightness ratio is within ~0.5% of a 128 grid's (32: ~2%), fine enough for auto's 3% bound.
    int pupilGrid = 64;
};

// Where rays are compared: the plane of focus (or the far plane), and the thick lens's lateral
// magnification from the film onto it.
struct ComparisonPlane {
    double z = 0;
    double magnification = 0;
};
ComparisonPlane comparisonPlane(const LensAnalysis& analysis);

// Samples film radii minFilmRadius to maxFilmRadius (mm) at the analysis's stop and focus.
std::vector<ThickLensFilmError> measureThickLensFilmError(const LensAnalysis& analysis, double minFilmRadius,
                                                          double maxFilmRadius,
                                                          const ThickLensFilmErrorOptions& options = {});

}  // namespace lenslab
