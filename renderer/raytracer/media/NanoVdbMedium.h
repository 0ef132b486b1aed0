#pragma once
// pbrt-v4's "nanovdb" medium: a density read from a NanoVDB float grid, trilinear between voxel
// centres, times sigma_a and sigma_s, over the box of the grid's active voxels (zero outside).
#include "media/NanoVdbFile.h"
#include "media/TrackedBoxMedium.h"

namespace lenslab {

class NanoVdbMedium final : public TrackedBoxMedium {
public:
    // mediumToWorld: the transform at MakeNamedMedium; the grid's own map takes index space to it.
    // The grid must hold an active voxel.
    NanoVdbMedium(NanoVdbGrid density, Vec3f sigmaA, Vec3f sigmaS, const Transform& mediumToWorld, HenyeyGreenstein phase);
    // The density at p in the medium's space (negative values read as zero).
    float density(Vec3f p) const;
    // The box of the active voxels in the medium's space (an axis-aligned bound of it when the
    // grid's map rotates): index min to max + 1 mapped, as NanoVDB's world bounding box.
    void bounds(Vec3f& lo, Vec3f& hi) const;

private:
    void coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const override;
    float densityAtIndex(Vec3f pIndex) const;

    NanoVdbGrid grid_;
    Vec3f sigmaA_, sigmaS_;
    Transform indexToMedium_;
    Vec3f indexMin_, indexExtent_;
};

// The majorants of sigma_t = density * sigmaT over the active voxels' index box (the medium's unit
// cube): up to 64 cells per axis, no more than one per voxel, each at least every stored value
// (voxel, tile, background) whose voxels reach into it by interpolation.
MajorantGrid nanoVdbMajorants(const NanoVdbGrid& g, float sigmaT);

}  // namespace lenslab
