#pragma once
// A tilt-shift mount: the whole lens turned and slid against the camera body and its film, as a
// view camera's standards or a tilt-shift lens do (Scheimpflug's plane of focus, rising front;
// docs/camera-conventions.md). The body's axes are camera space's (x right, y up, +z toward the
// scene); the film stays square to the body's z axis where the focused lens put it.
//
// The lens turns about its rear principal point P' (so a small tilt leaves the axial image where
// it was, to first order): first the tilt about the body's x axis (positive turns the lens's axis
// down, toward -y: a photographer's "tilt down" that lays the plane of focus toward the ground),
// then the swing about the body's y axis (positive turns it toward +x); then it slides across the
// film by the shift (positive x: right; positive y: rising front), in millimetres of the lens.
#include <array>

#include "prescription/FrameChange.h"

namespace lenslab {

struct LensMount {
    double tiltDegrees = 0;
    double swingDegrees = 0;
    std::array<double, 2> shiftMm{};
    bool isMoved() const { return tiltDegrees != 0 || swingDegrees != 0 || shiftMm != std::array<double, 2>{}; }
};

// The body coordinates of a lens-space point (and, by its rotation, of a direction) for a lens
// turning about the point of its axis at lens z = pivotZ. Throws OpticsError for a tilt or swing
// beyond 45 degrees or a shift beyond 100 mm (or not finite), naming the setting.
RigidMotion bodyFromLens(const LensMount& mount, double pivotZ);

}  // namespace lenslab
