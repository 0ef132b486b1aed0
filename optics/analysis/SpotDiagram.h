#pragma once
// The spot diagram of one field at one wavelength: where rays spread over the pupil meet the image
// plane, relative to a reference point (the analysis uses the d line's chief ray), with the
// spot's centroid and its RMS and largest (geometric) radius about the centroid.
#include <vector>

#include "prescription/LensSystem.h"
#include "analysis/PupilAiming.h"
#include "analysis/PupilSampling.h"

namespace lenslab {

struct SpotDiagram {
    double wavelength = 0;       // nm
    std::vector<Point2> points;  // mm on the image plane, minus the reference point
    Point2 centroid;             // mm, relative to the reference point
    double rmsRadius = 0;        // sqrt(mean |p - centroid|^2), mm
    double geometricRadius = 0;  // max |p - centroid|, mm
    int raysLaunched = 0;        // pupil points asked for (vignetted and unaimable ones included)
};

// `lens` at the spot's wavelength; `pupil` in normalised pupil coordinates. Blocked rays leave no
// point; with no point at all, the radii are 0.
SpotDiagram spotDiagram(const LensSystem& lens, const FieldAim& aim, double imageZ, Point2 reference,
                        const std::vector<Point2>& pupil);

}  // namespace lenslab
