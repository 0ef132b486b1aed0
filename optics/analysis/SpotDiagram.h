#pragma once
// Spot diagrams (docs/analysis.md, "Spot size"). The rays of one field at one wavelength are traced
// once, through an area-uniform quadrature of the stop (PupilSampling.h) over the part of it whose
// rays pass the lens, to a plane behind the lens; every image plane is then a straight move along
// each ray, so the paraxial, film and best planes come from the same rays. A spot's statistics weigh
// each ray by its share of the stop's area, so a vignetted field is measured over the light that
// arrives, and the arriving share is the field's transmission.
#include <optional>
#include <vector>

#include "analysis/PupilAiming.h"
#include "analysis/PupilSampling.h"
#include "prescription/LensSystem.h"

namespace lenslab {

// The rays of one field at one wavelength that leave the lens: where each crosses the plane z, its
// slopes (dx/dz, dy/dz) and its quadrature weight.
struct ImageRays {
    double wavelength = 0;       // nm
    double z = 0;                // the plane `at` lies on, lens z (mm)
    std::vector<Point2> at, slope;
    std::vector<double> weight;  // shares of the stop's area (a total of 1 with nothing vignetted)
    PupilQuadrature sampling;
    int launched = 0;            // quadrature nodes on passing stretches (the rims bisected apart)
    // |rms(sampling) / rms(sampling halved) - 1| about the centroid on the plane the sampling was
    // settled on; 0 where the spot has a single level.
    double samplingChange = 0;

    double arrivingWeight() const;
    Point2 pointOn(std::size_t i, double planeZ) const;
};

// The rays of the pupil quadrature (PupilSampling.h) over the passing part of the stop, centred on
// it: lines from the passing part's centroid, scaled by its spread, the stretches of each whose rays
// pass found by a scan and bisection to the rims. Doubles the quadrature from `start` until the RMS radius about the centroid on plane z moves by at
// most `tolerance` (relative) from one level to the next, or `maxAzimuths` is reached.
ImageRays settledImageRays(const LensSystem& lens, const FieldAim& aim, double z, PupilQuadrature start,
                           double tolerance, int maxAzimuths);

// Weighted statistics of points: their centroid, and the RMS and largest distance from `about`
// (their own centroid when none).
struct SpotStatistics {
    Point2 centroid;
    double rmsRadius = 0;        // sqrt(sum w |p - about|^2 / sum w), mm
    double geometricRadius = 0;  // max |p - about|, mm
};
SpotStatistics spotStatistics(const std::vector<Point2>& points, const std::vector<double>& weights,
                              std::optional<Point2> about = std::nullopt);

struct SpotDiagram {
    double wavelength = 0;       // nm
    std::vector<Point2> points;  // on the image plane, relative to the field's reference point, mm
    std::vector<double> weights; // each point's share of the launched pupil area
    SpotStatistics statistics;   // centroid relative to the reference point; radii about the spot's reference
    double transmission = 0;     // the arriving share of the pupil's area (1: nothing vignetted)
    int raysLaunched = 0;
    PupilQuadrature sampling;
    double samplingChange = 0;
};

// The rays on plane imageZ, as points relative to `origin`; radii about `about` (relative to origin
// as well) or, when none, about the spot's own centroid.
SpotDiagram spotDiagram(const ImageRays& rays, double imageZ, Point2 origin, std::optional<Point2> about = std::nullopt);

}  // namespace lenslab
