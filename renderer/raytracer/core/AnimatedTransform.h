#pragma once
// A transform that moves during the exposure: pbrt's two keyframes (ActiveTransform StartTime and
// EndTime), at the scene times TransformTimes names. Between them each keyframe's affine matrix is
// taken apart as M = T R S (translation, rotation, and an upper-triangular scale and shear S) and the
// parts are blended: T and S linearly, R by spherical interpolation of its quaternion. That is
// Embree's quaternion motion for instances, so a moving instance and every ray's own copy of its
// transform (the hit's shading frame, the camera) agree at every moment.
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

// One keyframe's parts: M = T R S.
struct TransformParts {
    double translation[3] = {0, 0, 0};
    Quaternion rotation;
    double stretch[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // upper triangular: scale and shear
};

class AnimatedTransform {
public:
    AnimatedTransform() = default;  // the identity, still
    // Throws std::domain_error when the keyframes differ and one of them is not affine.
    AnimatedTransform(const Transform& start, const Transform& end);

    bool moves() const { return moves_; }
    const Transform& start() const { return start_; }
    // The transform at `time`, a TransformTimes::fraction: the keyframes themselves at 0 and 1 (a
    // still transform is returned as given, so a scene without motion renders as it did before).
    Transform at(float time) const;
    // The keyframes' parts (moving transforms only), the end rotation on the start's side of the
    // quaternion sphere so that interpolation turns the short way.
    const TransformParts& startParts() const { return startParts_; }
    const TransformParts& endParts() const { return endParts_; }

private:
    Transform start_, end_;
    bool moves_ = false;
    TransformParts startParts_, endParts_;
};

}  // namespace lenslab
