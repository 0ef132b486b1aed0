#pragma once
// The ghost-focus analysis of a lens at its aperture and focus (Zemax's ghost focus, with the
// coatings' light): for every two-reflection path (trace/GhostPath.h) the paraxial image of the
// object it forms, where that lies from the film, how large the ghost of an on-axis point is on the
// film, how much of the direct image's light it carries and how bright it is beside the direct
// image, ranked brightest first. Paraxial, at the d line and normal incidence, on axis.
#include <atomic>
#include <vector>

#include "settings/LensAnalysis.h"
#include "trace/GhostPath.h"

namespace lenslab {

// A ghost whose blur on the film is smaller than this (mm) is flagged as focused near the film: a
// sharp, bright copy of the source (about 1/90 of a 35 mm frame's diagonal).
constexpr double kFocusedGhostDiameterMm = 0.5;
// The reference source of the relative intensity: a disc the sun's size, 0.533 deg across.
constexpr double kGhostSourceDiameterDegrees = 0.533;

struct GhostImage {
    GhostPath path;
    double reflectanceFirst = 0, reflectanceSecond = 0;  // the two reflections, at d, normal incidence
    double focusZ = 0;        // lens z of the ghost's paraxial image of the object; NaN: it leaves parallel
    double focusFromFilm = 0; // focusZ - film z (mm, + toward the lens); NaN with focusZ
    double blurDiameter = 0;  // the ghost of an on-axis point on the film (mm), vignetting applied
    double fieldScale = 0;    // the ghost's image height on the film over the direct image's (signed)
    double energy = 0;        // its light as a share of the direct image's (coatings, vignetting)
    // Its peak irradiance over the direct image's for a source of kGhostSourceDiameterDegrees:
    // energy * b_d^2 / max(a, b_g)^2 with a its blur radius and b_d, b_g the source's direct and
    // ghost image radii on the film (two concentric uniform discs' convolution peaks at 1 / the
    // larger's area).
    double relativeIntensity = 0;
    bool focused = false;     // blurDiameter < kFocusedGhostDiameterMm
};

struct GhostAnalysis {
    int reflectingSurfaces = 0;
    double filmZ = 0;
    double wavelength = kWavelengthD;
    std::vector<GhostImage> ghosts;  // all N (N - 1) / 2, brightest (relative intensity) first
};

// Throws OpticsError when the lens's own first order fails (it cannot be analysed at all). Set,
// `stop` ends the work between two ghosts (3,160 of them take 1.6 s through 80 surfaces): the
// answer holds the ghosts done so far, for a caller that set it to throw away.
GhostAnalysis analyzeGhosts(const LensAnalysis& analysis, const std::atomic<bool>* stop = nullptr);

}  // namespace lenslab
