#pragma once
// Tight bounds of the exit pupil as seen from each film radius, for aiming camera rays.
//
// From a film point, the rays that pass the whole lens cross a plane (the aiming plane: the rear
// vertex's, or the front vertex's behind a cover glass, ExitPupilBounds.cpp) inside a region: the stop's image cut by the rims of the other
// elements (the "cat's eye" of vignetting). A box around that region wastes a quarter of the rays
// on a double Gauss; here each region is a star-shaped polygon around its centroid, measured at a
// set of film radii with the exact trace, interpolated linearly between them and widened by a
// small margin so it always contains the passing rays. By rotational symmetry a film point at
// radius r and angle phi sees the region of the point (r, 0) rotated by phi, and that region is
// mirror-symmetric about y = 0.
//
// Millimetres, lens space (origin at the front vertex, +z toward the scene, film at negative z).
#include <atomic>
#include <functional>
#include <vector>

#include "prescription/LensSystem.h"
#include "prescription/OpticsError.h"
#include "trace/Vec3.h"

namespace lenslab {

struct ExitPupilBoundsOptions {
    int filmRadii = 64;      // film radii sampled from 0 to the maximum (whole-disc form)
    int vertices = 64;       // polygon vertices (even), at equal angles around the centre
    double margin = 0.01;    // relative widening of every polygon
    // Checked before each film radius (a radius costs ~1/64 of the whole, milliseconds even for a
    // lens at the surface limit): once set, the measurement stops by throwing SetupCancelled.
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double)> progress;  // after each radius: the fraction of radii measured
};

// The camera's setup was cancelled by the caller.
class SetupCancelled : public OpticsError {
public:
    SetupCancelled() : OpticsError("lens setup cancelled") {}
};

struct ExitPupilBounds {
    double filmZ = 0;          // film plane
    double aimZ = 0;           // aiming plane (the rear vertex's, or the front one's behind a cover glass)
    // Film radii measured: (firstRadius + i) * radiusStep for i < radiusCount(). A crop window
    // needs a ring of them; the same step keeps its regions identical to the whole frame's.
    double radiusStep = 0;
    int firstRadius = 0;
    int vertices = 0;
    std::vector<double> centreX;  // per film radius: region centre on the aiming plane (y = 0)
    std::vector<double> rho;      // per film radius, per vertex: distance from the centre; all 0 when
                                  // no ray passes
    // For sampling without rebuilding a polygon per ray: per pair of neighbouring radii (i, i + 1)
    // and vertex k <= vertices, the fan's area up to vertex k as three sums (A, B, C) so that at
    // the weight f between the two radii it is (1-f)^2 A + f(1-f) B + f^2 C; and the unit vector of
    // each vertex's direction (vertices + 1 of them, the last repeating the first).
    std::vector<double> fanAreas;
    std::vector<double> vertexX, vertexY;
    int radiusCount() const { return static_cast<int>(centreX.size()); }
    double minFilmRadius() const { return firstRadius * radiusStep; }
    double maxFilmRadius() const { return (firstRadius + radiusCount() - 1) * radiusStep; }
};

// Measures the regions with the exact trace (the lens's current stop opening) for film points at
// z = filmZ and radii k * radiusStep (mm), k = firstRadius to lastRadius; beyond that ring the
// nearest measured region is used, so callers cover every radius they will sample.
// options.filmRadii is unused here.
ExitPupilBounds computeExitPupilBounds(const LensSystem& lens, double filmZ, double radiusStep, int firstRadius,
                                       int lastRadius, const ExitPupilBoundsOptions& options = {});
// options.filmRadii radii over the whole disc, 0 to maxFilmRadius.
ExitPupilBounds computeExitPupilBounds(const LensSystem& lens, double filmZ, double maxFilmRadius,
                                       const ExitPupilBoundsOptions& options = {});

// A point drawn uniformly over the bounding region seen from a film point.
struct PupilSample {
    Vec3 point;        // on the aiming plane
    double area = 0;   // of the bounding region, mm^2 (the sample's pdf is 1 / area); 0 = no ray passes
};

// Maps (u1, u2) in [0,1)^2 to the region seen from film point (filmX, filmY); stratified inputs
// stay well stratified (fan triangles chosen by inverting the area CDF with u1).
PupilSample sampleExitPupil(const ExitPupilBounds& bounds, double filmX, double filmY, double u1, double u2);

// Many film points at once (structure of arrays), for the camera's batches: sample s's point is
// (x[s], y[s], aimZ) and the region's area area[s], bit for bit what sampleExitPupil returns (it is
// this with one sample). The other arrays are the stages' scratch.
struct PupilSampleBatch {
    std::vector<double> x, y, area;
    std::vector<double> radius, weight, target;
    std::vector<int> row, vertex;
    void resize(std::size_t n) {
        for (auto* v : {&x, &y, &area, &radius, &weight, &target}) v->resize(n);
        row.resize(n);
        vertex.resize(n);
    }
};
void sampleExitPupils(const ExitPupilBounds& bounds, std::size_t count, const double* filmX, const double* filmY,
                      const double* u1, const double* u2, PupilSampleBatch& out);

// Whether a point of the aiming plane lies inside the bounds seen from the film point.
bool insideExitPupilBounds(const ExitPupilBounds& bounds, double filmX, double filmY, double x, double y);

// Bounds for a spectral camera, one set per band of wavelengths [edgesNm[b], edgesNm[b + 1]], each
// holding the rays that pass at every wavelength of its band (narrow bands: few camera rays wasted,
// and each blocked ray is noise). The regions are measured at the lens's own wavelength, then each
// edge wavelength's boundary is found near them direction by direction (a bisection, a tenth of a
// measurement's rays); a band takes the larger of its two edges' distances in each direction, with
// the margin, as a region shifts smoothly with the wavelength. The rays they lose are measured in
// tests/optics/test_wavelength_etas.cpp.
struct SpectralExitPupilBounds {
    std::vector<double> edgesNm;
    std::vector<ExitPupilBounds> bands;
    std::size_t bandOf(double nm) const;  // wavelengths beyond the edges take the nearest band
    const ExitPupilBounds& at(double nm) const { return bands[bandOf(nm)]; }
};

SpectralExitPupilBounds computeSpectralExitPupilBounds(const LensSystem& lens, double filmZ, double radiusStep,
                                                       int firstRadius, int lastRadius,
                                                       const std::vector<double>& edgesNm,
                                                       const ExitPupilBoundsOptions& options = {});

// sampleExitPupils with each sample in the bounds of its wavelength nm[s].
void sampleSpectralExitPupils(const SpectralExitPupilBounds& bounds, std::size_t count, const double* filmX,
                              const double* filmY, const double* u1, const double* u2, const double* nm,
                              PupilSampleBatch& out);

}  // namespace lenslab
