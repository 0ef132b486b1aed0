#pragma once
// A medium whose coefficients vary over a box and are zero outside it, bounded by majorants over a
// coarse grid of cells (one cell: one majorant): distances by delta tracking, transmittance by
// ratio tracking, both walking the cells. Subclasses give the coefficients.
#include "media/MajorantGrid.h"
#include "media/ParticipatingMedium.h"

namespace lenslab {

class TrackedBoxMedium : public ParticipatingMedium {
public:
    MediumEvent sample(Vec3f o, Vec3f d, float tMax, int hero, Pcg32& rng) const final;
    Vec3f transmittance(Vec3f o, Vec3f d, float tMax, Pcg32& rng) const final;

protected:
    // boxToWorld maps the unit cube onto the box in the world; no channel of sigma_a + sigma_s
    // anywhere in a cell exceeds the cell's majorant.
    TrackedBoxMedium(const Transform& boxToWorld, MajorantGrid majorants, HenyeyGreenstein phase);
    // The coefficients at pBox in the unit cube's coordinates.
    virtual void coefficients(Vec3f pBox, Vec3f& sigmaA, Vec3f& sigmaS) const = 0;

private:
    // Where the ray o + t d (world) runs inside the box, clipped to [0, tMax]; false if nowhere.
    // oBox, dBox: the ray in the box's unit-cube coordinates, with the same t.
    bool clip(Vec3f o, Vec3f d, float tMax, Vec3f& oBox, Vec3f& dBox, float& t0, float& t1) const;
    // Tentative collisions along the box-space ray from t0 to t1 at each cell's majorant rate (the
    // exponential draw starts afresh in each cell: it is memoryless). At each,
    // collide(t, sigmaA, sigmaS, majorant) returns false to end the walk.
    template <class Collide>
    void walkCollisions(Vec3f oBox, Vec3f dBox, float t0, float t1, Pcg32& rng, Collide collide) const;

    Transform worldToBox_;
    MajorantGrid majorants_;
};

}  // namespace lenslab
