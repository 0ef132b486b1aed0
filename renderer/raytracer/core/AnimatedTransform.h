#pragma once
// A transform that moves during the exposure: pbrt's two keyframes (ActiveTransform StartTime and
// EndTime), at the scene times TransformTimes names. In between it moves as in pbrt-v3 and pbrt-v4:
// each keyframe's affine matrix is taken apart by polar decomposition, M = T R P (translation,
// rotation, symmetric stretch), and the parts are blended, T and P linearly, R by spherical
// interpolation of its quaternion the short way round.
// Embree's quaternion motion blends a different split, M = T R S with S upper triangular
// (Gram-Schmidt), between its time steps. Where that split moves the same way (translations,
// rotations, scales along the object's own axes: nearly every scene) the two keyframes are its two
// time steps; where it does not (a stretch across the turning axes) pbrt's motion is sampled at
// kMotionSteps + 1 even moments, and Embree blends between neighbours. at() blends the same steps,
// so a moving instance and every ray's own copy of its transform (the hit's shading frame, the
// camera) agree at every moment.
#include <vector>

#include "core/Transform.h"

namespace lenslab {

// The scene times of the two keyframes (TransformTimes; pbrt's default 0 1).
struct TransformTimes {
    double start = 0, end = 1;
    // How far scene time t lies from the start keyframe to the end one, in [0, 1]: the keyframes hold
    // before start and after end, as in pbrt. This is the time Embree's rays carry.
    float fraction(double t) const;
};

struct Quaternion {
    double r = 1, i = 0, j = 0, k = 0;
};

// One time step's parts in Embree's form: M = T R S.
struct TransformParts {
    double translation[3] = {0, 0, 0};
    Quaternion rotation;
    double stretch[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // upper triangular: scale and shear
};

class AnimatedTransform {
public:
    // Time steps where the Gram-Schmidt blend strays from pbrt's motion. The error falls as the
    // square of the step: for a 60 degree turn of a 2:1 stretch at most 6e-5 of the object's size,
    // against 0.039 with the two keyframes alone.
    static constexpr int kMotionSteps = 32;

    AnimatedTransform() = default;  // the identity, still
    // Throws std::domain_error when the keyframes differ and one of them is not affine.
    AnimatedTransform(const Transform& start, const Transform& end);

    bool moves() const { return moves_; }
    const Transform& start() const { return start_; }
    // The transform at `time`, a TransformTimes::fraction: the keyframes themselves at 0 and 1 (a
    // still transform is returned as given, so a scene without motion renders as it did before).
    Transform at(float time) const;
    // Embree's time steps, evenly spread over the fractions 0 to 1 (moving transforms only: 2 or
    // kMotionSteps + 1), each rotation on its predecessor's side of the quaternion sphere so that
    // interpolation turns the short way.
    const std::vector<TransformParts>& steps() const { return steps_; }

private:
    Transform start_, end_;
    bool moves_ = false;
    std::vector<TransformParts> steps_;
};

}  // namespace lenslab
