#pragma once
// The render against the analysis: one edge of the slanted-edge chart (scenes/slanted-edge.pbrt)
// rendered through a lens, a crop of the film around its image measured by the e-SFR
// (optics/analysis/SlantedEdgeSfr.h), beside what the analysis predicts for that crop: the
// geometric polychromatic MTF on the film plane at the edge's field (the ray tracer has no
// diffraction), sagittal for an edge along the field's radius and tangential for one across it,
// times the pixel's own MTF (a square pixel integrated whole: the scene's one-pixel box filter).
//
// The lens is rendered and analysed at one wavelength set: a lens without dispersion renders in
// RGB, its every wavelength alike, against the analysis's F, d and C; a dispersive lens renders at
// its primary wavelength only, against the analysis at that wavelength.
#include <optional>
#include <string>
#include <vector>

#include "analysis/GeometricMtf.h"
#include "analysis/SlantedEdgeSfr.h"

namespace lenslab {

// scenes/slanted-edge.pbrt as it lays the chart out, and the film the comparison renders on.
constexpr const char* kSlantedEdgeSceneId = "slanted-edge";
constexpr double kChartDistanceMm = 5000;  // front vertex to the chart, the plane of focus
constexpr double kChartStepDegrees = 2;    // an edge every 2 degrees (from the front vertex) ...
constexpr int kChartSteps = 20;            // ... up to 40: tangential above the axis, sagittal below
// Portrait, so that the edges up the chart's vertical axis reach 0.7 of the corner's field.
constexpr int kFilmWidthPixels = 6000, kFilmHeightPixels = 9000;
constexpr double kFilmDiagonalMm = 43.2666153;  // 24 x 36 mm: 4 um pixels

struct EdgeCase {
    std::string scenePath, lensPath;
    std::optional<double> fstop;   // none: the widest
    int chartStep = 0;             // the edge at chartStep * kChartStepDegrees; 0: on the axis (tangential)
    MtfDirection direction = MtfDirection::Tangential;
    int cropPixels = 64;
    int spp = 256;
    int threads = 0;
};

struct EdgeComparison {
    double fieldDegrees = 0;        // the edge's object point seen from the entrance pupil, as analysed
    MtfDirection direction = MtfDirection::Tangential;
    double fstop = 0;
    double pixelMm = 0;
    double filmX = 0, filmY = 0;    // the measured edge's centre on the film, lens space mm
    EdgeSfr edge;                   // the crop's e-SFR (cycles per pixel)
    std::vector<double> frequencies;  // lp/mm, 0 to the pixel Nyquist
    std::vector<double> measured;     // the render's e-SFR
    std::vector<double> lens;         // the analysis's geometric MTF, film plane
    std::vector<double> pixel;        // the square pixel's MTF along the edge's normal
    std::vector<double> predicted;    // lens x pixel
    double maxDifference = 0;         // |measured - predicted| up to half the pixel Nyquist
};

// Throws SettingError, OpticsError or SceneError (bad lens or settings), std::out_of_range when the
// edge's image leaves the film, std::invalid_argument (no edge in the crop), std::runtime_error when
// the analysis traces no ray at the edge's field or the edge found is not the chart's (the scene and
// the layout above disagree).
EdgeComparison compareSlantedEdge(const EdgeCase& c);

}  // namespace lenslab
