#pragma once
// Decentres and tilts: how a file moves a surface (and the surfaces after it) off the axis, and the
// rigid motion of coordinates that it becomes (docs/prescriptions.md, "Tilts, decentres and folds").
#include <array>
#include <cstdint>

namespace lenslab {

// What happens to the coordinates after the decentred surface (Code V's words; a Zemax coordinate
// break is a Basic decentre of a surface that does nothing else).
enum class FrameMode : std::uint8_t {
    Basic,              // the surface and every one after it follow the new axis
    DecentreAndReturn,  // DAR: only this surface moves; after it the axis is the one before
    Bend,               // BEN: after the surface the axis turns by the tilt once more (a fold mirror)
    Reverse,            // REV: the surface stays; after it the inverse decentre and tilt apply
};

// The order of the motions: Code V and Zemax's order flag 0 decentre, then tilt about x, the new y
// and the newest z; Zemax's flag 1 tilts about z, then y, then x, then decentres along the new axes.
enum class TiltOrder : std::uint8_t { DecentreThenTilt, TiltThenDecentre };

// As the file states it: lengths in mm, angles in degrees, in the file's axes (z along the light
// entering the surface). Tilt signs follow Code V's ADE, BDE, CDE (Zemax's tilts about x, y, z alike).
struct FrameChange {
    std::array<double, 3> decentre{};  // XDE YDE ZDE / Zemax decentre x, y (z from the thickness)
    std::array<double, 3> tiltDegrees{};  // ADE BDE CDE / Zemax tilt about x, y, z
    FrameMode mode = FrameMode::Basic;
    TiltOrder order = TiltOrder::DecentreThenTilt;
    bool isIdentity() const {
        return decentre == std::array<double, 3>{} && tiltDegrees == std::array<double, 3>{} && mode != FrameMode::Bend;
    }
};

// New coordinates of a point from old ones, in lens space (+z toward the scene): p' = R p + t with
// R orthogonal (determinant -1 where the image space is mirrored after an odd number of mirrors).
// Directions transform with R alone.
struct RigidMotion {
    std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major
    std::array<double, 3> shift{};

    static RigidMotion identity() { return {}; }
    bool isIdentity() const { return *this == RigidMotion{}; }
    bool operator==(const RigidMotion& o) const { return rotation == o.rotation && shift == o.shift; }
    // First this, then `next`.
    RigidMotion then(const RigidMotion& next) const;
    RigidMotion inverse() const;
    std::array<double, 3> applyToPoint(const std::array<double, 3>& p) const;
    std::array<double, 3> applyToDirection(const std::array<double, 3>& d) const;
};

// The motions a FrameChange makes at a surface whose vertex lies at lens z `vertexZ` (on the axis of
// the coordinates arriving there): `before` takes the arriving coordinates to the surface's own
// (vertex back at (0, 0, vertexZ)), `after` those to the coordinates the next surface is placed in.
struct SurfaceMotions {
    RigidMotion before, after;
};
SurfaceMotions surfaceMotions(const FrameChange& change, double vertexZ);

}  // namespace lenslab
