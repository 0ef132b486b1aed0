#pragma once
// The thick-lens approximation of Kolb, Mitchell & Hanrahan (1995): the whole lens replaced by its
// principal planes and focal length. Object points map to image points by the 4x4 projective
// matrix T = Translate(P') * M * Translate(-P), with M = [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,-1/f,1]]
// in homogeneous coordinates (z measured from the principal plane, +z toward the scene). Rays
// cross the gap between P and P' at unchanged height; the pupils stand in for the stop.
#include <array>
#include <vector>

#include "trace/ExactTrace.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Pupils.h"

namespace lenslab {

using Matrix4 = std::array<std::array<double, 4>, 4>;

struct ThickLens {
    double f = 0;
    double zP = 0, zPPrime = 0;
    Pupil entrance, exit;
};

ThickLens makeThickLens(const FirstOrder& fo, const Pupils& pupils);

// The object-to-image matrix T above, and its inverse (image to object).
Matrix4 objectToImageMatrix(const ThickLens& lens);
Matrix4 imageToObjectMatrix(const ThickLens& lens);

// Traces a ray through the thick lens. The result starts on the outgoing principal plane. A ray
// outside the pupil (exit pupil from the film, entrance pupil from the scene) is ClippedByStop.
TraceResult traceThick(const ThickLens& lens, const Ray& ray, TraceDirection direction);

// The thick-lens error against the exact trace for rays parallel to the axis entering at height h
// (surface 0 aperture permitting): where each crosses the exact paraxial focal plane z = F'.
struct ThickLensErrorSample {
    double height = 0;           // entrance height, mm
    double transverseError = 0;  // exact minus thick height at the F' plane, mm
    double angleError = 0;       // exact minus thick ray angle to the axis, radians
    bool blocked = false;        // the exact ray was blocked (values are then 0)
};
std::vector<ThickLensErrorSample> thickLensError(const LensSystem& lens, const ThickLens& thick,
                                                 const FirstOrder& fo, const std::vector<double>& heights);

}  // namespace lenslab
