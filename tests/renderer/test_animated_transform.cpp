// Moving transforms: the keyframes themselves at the ends, translation, rotation (the short way
// round) and scale blended part by part in between as pbrt blends them (a stretch across the turn
// included), and the scene times mapped to the fraction rays carry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/AnimatedTransform.h"

namespace lenslab {
namespace {

void expectSameMatrix(const Transform& a, const Transform& b, double tolerance) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a.forward.m[r][c], b.forward.m[r][c], tolerance) << r << "," << c;
}

TEST(AnimatedTransform, EqualKeyframesStandStillAndReturnTheTransformAsGiven) {
    const Transform t = translate(1, 2, 3) * rotate(30, 1, 1, 0) * scale(2, 1, 1);
    const AnimatedTransform still(t, t);
    EXPECT_FALSE(still.moves());
    const Transform mid = still.at(0.5f);
    EXPECT_EQ(0, std::memcmp(&mid, &t, sizeof t));
}

TEST(AnimatedTransform, KeyframesHoldAtTheEnds) {
    const Transform a = rotate(10, 0, 0, 1), b = translate(0, 1, 0) * rotate(50, 0, 0, 1);
    const AnimatedTransform m(a, b);
    ASSERT_TRUE(m.moves());
    expectSameMatrix(m.at(0), a, 0);
    expectSameMatrix(m.at(1), b, 0);
}

TEST(AnimatedTransform, MidwayTurnsHalfTheAngleAndTravelsHalfTheWay) {
    const AnimatedTransform m(translate(-1, 0, 2), translate(1, 4, 2) * rotate(90, 0, 0, 1));
    expectSameMatrix(m.at(0.5f), translate(0, 2, 2) * rotate(45, 0, 0, 1), 1e-12);
    expectSameMatrix(m.at(0.25f), translate(-0.5, 1, 2) * rotate(22.5, 0, 0, 1), 1e-7);  // the fraction is a float
}

TEST(AnimatedTransform, RotationTakesTheShortWayRound) {
    // 0 to 270 degrees is -90 the short way: midway stands at -45.
    const AnimatedTransform m(Transform{}, rotate(270, 1, 0, 0));
    expectSameMatrix(m.at(0.5f), rotate(-45, 1, 0, 0), 1e-12);
}

// The short way across 180 degrees: 170 to -170 is 20 degrees through 180, and -60 to -170 is 110
// degrees through -115 (not 250 through 65). Shepperd's method gives the second pair's quaternions
// on opposite sides of the quaternion sphere (-60 degrees from the trace, scalar part positive;
// -170 from the axis component, made positive), so only brought to one side does the blend take the
// short way; a blend that ignored the sides would stand at 65 degrees midway.
TEST(AnimatedTransform, RotationTakesTheShortWayAcross180Degrees) {
    for (const float axis : {0.0f, 1.0f}) {
        const float x = axis, y = 1 - axis;
        expectSameMatrix(AnimatedTransform(rotate(170, x, y, 0), rotate(-170, x, y, 0)).at(0.5f), rotate(180, x, y, 0), 1e-12);
        const AnimatedTransform m(rotate(-60, x, y, 0), rotate(-170, x, y, 0));
        expectSameMatrix(m.at(0.5f), rotate(-115, x, y, 0), 1e-12);
        expectSameMatrix(m.at(0.25f), rotate(-87.5, x, y, 0), 1e-6);
    }
}

TEST(AnimatedTransform, ScaleBlendsLinearly) {
    const AnimatedTransform m(rotate(40, 0, 1, 0), rotate(40, 0, 1, 0) * scale(3, 2, 1));
    expectSameMatrix(m.at(0.5f), rotate(40, 0, 1, 0) * scale(2, 1.5, 1), 1e-12);
}

Matrix44 blended(const Matrix44& a, const Matrix44& b, double f) {
    Matrix44 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m.m[r][c] = (1 - f) * a.m[r][c] + f * b.m[r][c];
    return m;
}

TEST(AnimatedTransform, AStretchAcrossTheTurnMovesAsInPbrt) {
    // S then a 60 degree turn: pbrt splits the end keyframe S R into the rotation R and the
    // symmetric stretch R^T S R, and blends those: R(60 f) ((1 - f) S + f R^T S R). A single
    // Gram-Schmidt blend of the keyframes (rotation 0 to 40.9 degrees) strays by up to 0.039.
    const Transform S = scale(1, 0.5, 1), R = rotate(60, 0, 0, 1);
    const AnimatedTransform m(S, S * R);
    EXPECT_EQ(m.steps().size(), std::size_t(AnimatedTransform::kMotionSteps + 1));
    const Matrix44 endStretch = transpose(R.forward) * S.forward * R.forward;
    double worst = 0;
    for (int k = 1; k < 100; ++k) {
        const float f = k / 100.0f;
        const Matrix44 want = rotate(60 * double(f), 0, 0, 1).forward * blended(S.forward, endStretch, f);
        const Matrix44 got = m.at(f).forward;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) worst = std::max(worst, std::fabs(got.m[r][c] - want.m[r][c]));
    }
    EXPECT_LT(worst, 1e-4);
    // At the time steps themselves (here f = 1/2) the motion is pbrt's to rounding.
    expectSameMatrix(m.at(0.5f), rotate(30, 0, 0, 1) * makeTransform(blended(S.forward, endStretch, 0.5)), 1e-12);
}

TEST(AnimatedTransform, MotionsWithoutACrossStretchKeepTwoSteps) {
    // Turns, shifts, scales along the object's own axes and mirrors: Embree's blend of the two
    // keyframes is pbrt's motion already.
    EXPECT_EQ(AnimatedTransform(translate(1, 0, 0), translate(0, 2, 1) * rotate(170, 1, 2, 3)).steps().size(), 2u);
    EXPECT_EQ(AnimatedTransform(rotate(20, 0, 1, 0) * scale(3, 1, 2), rotate(80, 0, 1, 0) * scale(1, 2, 2)).steps().size(), 2u);
    const AnimatedTransform mirrored(scale(-1, 1, 1), scale(-1, 1, 1) * rotate(90, 0, 0, 1));
    EXPECT_EQ(mirrored.steps().size(), 2u);
    expectSameMatrix(mirrored.at(0.5f), scale(-1, 1, 1) * rotate(45, 0, 0, 1), 1e-12);
}

TEST(AnimatedTransform, PerspectiveKeyframesAreRefused) {
    Matrix44 p;
    p.m[3][2] = 1;
    p.m[3][3] = 0;
    EXPECT_THROW(AnimatedTransform(Transform{}, makeTransform(p)), std::domain_error);
}

TEST(TransformTimes, FractionIsLinearBetweenTheTimesAndHoldsOutside) {
    const TransformTimes times{2, 4};
    EXPECT_EQ(times.fraction(1), 0.0f);
    EXPECT_EQ(times.fraction(2), 0.0f);
    EXPECT_FLOAT_EQ(times.fraction(3), 0.5f);
    EXPECT_EQ(times.fraction(4), 1.0f);
    EXPECT_EQ(times.fraction(9), 1.0f);
    const TransformTimes instant{1, 1};  // pbrt: the start keyframe up to the time, the end one after
    EXPECT_EQ(instant.fraction(1), 0.0f);
    EXPECT_EQ(instant.fraction(1.5), 1.0f);
}

}  // namespace
}  // namespace lenslab
