#pragma once
// Where camera rays from a film that is not square to the lens axis can pass: the film of a tilted
// or shifted lens (a tilt-shift lens, docs/camera-conventions.md). ExitPupilBounds relies on the
// film being the plane z = const and the lens being rotationally symmetric about its axis; here
// neither holds, so the passing region is measured at the nodes of a grid over the film itself and
// described by a circle on the aiming plane, which is cheap to sample and to interpolate: between nodes a film point takes the smallest circle around the interpolated centre
// that holds its four nodes' circles, widened by a margin. A circle holds more than the cat's-eye
// polygon does, so a tilted lens wastes more camera rays than a square one (measured in
// tests/renderer/test_tilt_shift.cpp); it is the price of not assuming any symmetry. The aiming
// plane is best the exit pupil's, where every film point's region is the pupil itself, cut by
// vignetting: the regions hardly move across the film and the circles between nodes stay tight.
//
// Millimetres, lens space (origin at the front vertex, +z toward the scene, film at negative z).
#include <vector>

#include "prescription/LensSystem.h"
#include "trace/Vec3.h"

namespace lenslab {

// A film plane in lens space: film point (u, v) lies at origin + u * uAxis + v * vAxis.
struct FilmPlane {
    Vec3 origin;
    Vec3 uAxis{1, 0, 0}, vAxis{0, 1, 0};  // unit, orthogonal
    Vec3 normal() const;                  // toward the lens
    Vec3 at(double u, double v) const { return origin + u * uAxis + v * vAxis; }
};

// A disc of the aiming plane; radius 0: no ray passes.
struct PupilCircle {
    double x = 0, y = 0, radius = 0;
};

struct FilmPlanePupilBounds {
    FilmPlane film;
    double aimZ = 0;                   // the aiming plane
    double halfU = 0, halfV = 0;       // the grid covers [-halfU, halfU] x [-halfV, halfV]
    int nodesU = 0, nodesV = 0;
    std::vector<PupilCircle> nodes;    // row-major, v outer
    double margin = 0.01;              // relative widening of every interpolated circle
};

// Measures the passing regions from film points (u, v), |u| <= halfU, |v| <= halfV, on the plane
// z = aimZ (in front of every film point; the search starts over a square of half-width 1.5 x
// aimRadius around the axis), with the exact trace at the lens's wavelength through its current
// stop. Throws OpticsError when some film point lies in front of the rear surface (the tilted film
// would cut into the lens).
FilmPlanePupilBounds computeFilmPlanePupilBounds(const LensSystem& lens, const FilmPlane& film, double halfU,
                                                 double halfV, double aimZ, double aimRadius, int nodesU = 9,
                                                 int nodesV = 7);

// The circle that holds the rays passing from film point (u, v).
PupilCircle filmPlanePupilCircle(const FilmPlanePupilBounds& bounds, double u, double v);

}  // namespace lenslab
