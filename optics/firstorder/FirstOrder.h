#pragma once
// Cardinal points of the lens, from near-axis rays traced from each side.
#include "prescription/LensSystem.h"

namespace lenslab {

// All z in the lens convention: origin at the front vertex, +z toward the scene (mm).
struct FirstOrder {
    double efl = 0;       // effective focal length, image side (P' to F')
    double eflFront = 0;  // object side (F to P); equals efl for a lens in air
    double zF = 0;        // front (object-side) focal point
    double zFPrime = 0;   // rear (image-side) focal point
    double zP = 0;        // front principal plane
    double zPPrime = 0;   // rear principal plane
    // Rear vertex to F', and F to the front vertex; for a decentred lens, from where its axis ray
    // meets the outermost surfaces that bend light (its vertices and dummy surfaces lie off it).
    double backFocalDistance = 0;
    double frontFocalDistance = 0;
};

// Throws AfocalError for an afocal system, OpticsError for one a near-axis ray cannot pass.
FirstOrder computeFirstOrder(const LensSystem& lens);

}  // namespace lenslab
