#pragma once
// Where the analysis samples the pupil (docs/analysis.md, "Pupil sampling"): a polar quadrature over
// the aperture stop (normalised: the unit disk), equally spaced azimuths and, along each azimuth's
// line from the centre, Gauss-Legendre nodes in u = r^2 over each stretch of the line whose rays
// pass the lens. The area element is dA = du dphi / 2, so equal steps of u are equal areas; with the
// stretches' ends found on the vignetting rims themselves, `rings` nodes integrate a polynomial in
// r^2 of degree 2 rings - 1 exactly over each stretch, and `azimuths` points every azimuthal harmonic
// below `azimuths`. SpotDiagram.h centres the polar lines inside the passing part of the stop.
#include <utility>
#include <vector>

namespace lenslab {

struct Point2 {
    double x = 0, y = 0;
};

// Along a line, the integrand (a ray's image point, smooth across the pupil) is polynomial-like
// between the rims, so 8 nodes per stretch are exact to far below a spot's last digit; the azimuths
// are what a spot needs more of, where rims meet at corners of a vignetted pupil.
struct PupilQuadrature {
    int rings = 8;      // Gauss-Legendre nodes per passing stretch of a line
    int azimuths = 16;  // lines, equally spaced from +y (the tangential section) toward +x
    PupilQuadrature doubled() const { return {rings, 2 * azimuths}; }
};

// The Gauss-Legendre rule of order n on [0, 1]: (node, weight) pairs, weights summing to 1. Throws
// std::invalid_argument unless 1 <= n <= 256.
std::vector<std::pair<double, double>> gaussLegendreUnit(int n);

// The unit vector of azimuth k of n: (sin phi, cos phi), phi = 2 pi k / n.
Point2 azimuthDirection(int k, int n);

}  // namespace lenslab
