// Moving transforms: the keyframes themselves at the ends, translation, rotation (the short way
// round) and scale blended part by part in between, and the scene times mapped to the fraction rays carry.
#include <gtest/gtest.h>

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

TEST(AnimatedTransform, ScaleBlendsLinearly) {
    const AnimatedTransform m(rotate(40, 0, 1, 0), rotate(40, 0, 1, 0) * scale(3, 2, 1));
    expectSameMatrix(m.at(0.5f), rotate(40, 0, 1, 0) * scale(2, 1.5, 1), 1e-12);
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
