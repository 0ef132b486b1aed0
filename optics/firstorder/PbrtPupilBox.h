#pragma once
// pbrt-v3's realistic camera, with `simpleweighting` (its default), samples each film point's
// exit-pupil bounding box uniformly and weights a ray cos^4 times the area of that box over the
// first box's; rays the lens blocks score 0. Its pixel is then the irradiance integral
// (integral of cos^4 dA over the passing part of the rear vertex's plane, over the film distance
// squared) times d^2 / A0, d the film's distance from the rear vertex and A0 the first box's
// area. lenslab's weights are that irradiance integral, so d^2 / A0 is the whole of pbrt-v3's
// exposure, whatever lenslab's own pupil bounds are.
#include "prescription/LensSystem.h"

namespace lenslab {

// The area (mm^2) of pbrt-v3's first exit-pupil box as pbrt-v3 builds it: on the plane of the rear
// vertex, the points within 1.5 rear-element radii that pass light from the film segment between
// the centre and 1/64 of the half-diagonal, their bounds grown on each side by two of pbrt-v3's
// 1024 sample spacings along the sampled square's diagonal. 0 when no light passes.
// filmZ: the film's z in lens space (mm).
double pbrtFirstPupilBoxArea(const LensSystem& lens, double filmZ, double filmDiagonalMm);

}  // namespace lenslab
