#pragma once
// How much light reaches each film radius compared with the film centre, by exact tracing.
//
// The irradiance at a film point x' from a uniform, Lambertian scene is (Kolb et al. 1995, eq. 2)
//   E(x') = L / Z^2 * integral over the rays that pass the lens of cos^4(theta) dA,
// with the integral taken over any plane parallel to the film at distance Z (here the aiming plane
// at the rear vertex) and theta the angle of the ray to the axis. The passing set is the exit pupil
// as the film point sees it, clipped by element rims off axis (vignetting). Transmission losses
// (reflections, absorption) are ignored, as in the renderer.
//
// Millimetres, lens space (origin at the front vertex, +z toward the scene, film at negative z).
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct IlluminationSample {
    double filmRadius = 0;            // mm from the axis on the film
    double passingArea = 0;           // area of the passing region on the aiming plane, relative to the centre's
    double relativeIllumination = 0;  // E(r) / E(0): passing area weighted by cos^4(theta)
};

struct RelativeIlluminationOptions {
    int filmRadii = 48;  // samples from 0 to maxFilmRadius
    int grid = 128;      // grid points per side over the passing region's bounding box (even)
};

// Traces grids of rays from film points (r, 0, filmZ) to the aiming plane (rear vertex) with
// traceBatch. Throws OpticsError when the film does not lie behind the lens or no ray passes from
// the film centre.
std::vector<IlluminationSample> relativeIllumination(const LensSystem& lens, double filmZ, double maxFilmRadius,
                                                     const RelativeIlluminationOptions& options = {});

// The largest film radius (up to `limit`) from which some ray still passes the lens: the edge of
// the image circle. Bisection on the passing test; 0 when nothing passes from the centre.
// The cosine-fourth law's factor for a ray at cosine c to the axis.
inline double cos4(double c) { return (c * c) * (c * c); }

double imageCircleRadius(const LensSystem& lens, double filmZ, double limit);

}  // namespace lenslab
