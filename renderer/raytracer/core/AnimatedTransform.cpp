#include "core/AnimatedTransform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lenslab {

float TransformTimes::fraction(double t) const {
    if (t <= start) return 0;
    if (t >= end) return 1;
    return float((t - start) / (end - start));
}

namespace {

bool sameMatrix(const Matrix44& a, const Matrix44& b) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (a.m[r][c] != b.m[r][c]) return false;
    return true;
}

double dot(const Quaternion& a, const Quaternion& b) { return a.r * b.r + a.i * b.i + a.j * b.j + a.k * b.k; }

// The unit quaternion of a rotation matrix (Shepperd's method: divide by the largest of the four
// candidates, never by a small one).
Quaternion quaternionOf(const double R[3][3]) {
    const double trace = R[0][0] + R[1][1] + R[2][2];
    if (trace > 0) {
        const double s = 2 * std::sqrt(trace + 1);
        return {s / 4, (R[2][1] - R[1][2]) / s, (R[0][2] - R[2][0]) / s, (R[1][0] - R[0][1]) / s};
    }
    if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
        const double s = 2 * std::sqrt(1 + R[0][0] - R[1][1] - R[2][2]);
        return {(R[2][1] - R[1][2]) / s, s / 4, (R[0][1] + R[1][0]) / s, (R[0][2] + R[2][0]) / s};
    }
    if (R[1][1] > R[2][2]) {
        const double s = 2 * std::sqrt(1 + R[1][1] - R[0][0] - R[2][2]);
        return {(R[0][2] - R[2][0]) / s, (R[0][1] + R[1][0]) / s, s / 4, (R[1][2] + R[2][1]) / s};
    }
    const double s = 2 * std::sqrt(1 + R[2][2] - R[0][0] - R[1][1]);
    return {(R[1][0] - R[0][1]) / s, (R[0][2] + R[2][0]) / s, (R[1][2] + R[2][1]) / s, s / 4};
}

void rotationOf(const Quaternion& q, double R[3][3]) {
    const double n = std::sqrt(dot(q, q)), r = q.r / n, i = q.i / n, j = q.j / n, k = q.k / n;
    R[0][0] = 1 - 2 * (j * j + k * k); R[0][1] = 2 * (i * j - k * r);     R[0][2] = 2 * (i * k + j * r);
    R[1][0] = 2 * (i * j + k * r);     R[1][1] = 1 - 2 * (i * i + k * k); R[1][2] = 2 * (j * k - i * r);
    R[2][0] = 2 * (i * k - j * r);     R[2][1] = 2 * (j * k + i * r);     R[2][2] = 1 - 2 * (i * i + j * j);
}

// M = T R S with S upper triangular: Gram-Schmidt on the linear part's columns gives R's columns and
// S; a mirror stays in S (a negative last scale) so that R is a rotation.
TransformParts partsOf(const Matrix44& m) {
    const auto& a = m.m;
    if (a[3][0] != 0 || a[3][1] != 0 || a[3][2] != 0 || a[3][3] != 1)
        throw std::domain_error("a moving transform must be affine (no perspective)");
    TransformParts p;
    double q[3][3] = {};  // R's columns, q[c][row]
    for (int c = 0; c < 3; ++c) {
        double v[3] = {a[0][c], a[1][c], a[2][c]};
        for (int prev = 0; prev < c; ++prev) {
            const double d = q[prev][0] * v[0] + q[prev][1] * v[1] + q[prev][2] * v[2];
            p.stretch[prev][c] = d;
            for (int row = 0; row < 3; ++row) v[row] -= d * q[prev][row];
        }
        const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(len > 0)) throw std::domain_error("singular transform");
        p.stretch[c][c] = len;
        for (int row = 0; row < 3; ++row) q[c][row] = v[row] / len;
    }
    const double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) - q[1][0] * (q[0][1] * q[2][2] - q[0][2] * q[2][1]) +
                       q[2][0] * (q[0][1] * q[1][2] - q[0][2] * q[1][1]);
    if (det < 0) {
        for (int row = 0; row < 3; ++row) q[2][row] = -q[2][row];
        p.stretch[2][2] = -p.stretch[2][2];
    }
    double R[3][3];
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) R[row][c] = q[c][row];
    p.rotation = quaternionOf(R);
    for (int row = 0; row < 3; ++row) p.translation[row] = a[row][3];
    return p;
}

Quaternion slerp(const Quaternion& a, const Quaternion& b, double f) {
    const double c = dot(a, b);
    double wa = 1 - f, wb = f;
    if (c < 0.9995) {  // else nearly parallel: a linear blend, normalised by rotationOf, is as exact
        const double theta = std::acos(c);
        wa = std::sin((1 - f) * theta) / std::sin(theta);
        wb = std::sin(f * theta) / std::sin(theta);
    }
    return {wa * a.r + wb * b.r, wa * a.i + wb * b.i, wa * a.j + wb * b.j, wa * a.k + wb * b.k};
}

// b, or -b (the same rotation) where that lies on a's side of the quaternion sphere.
Quaternion nearSide(const Quaternion& a, const Quaternion& b) {
    return dot(a, b) < 0 ? Quaternion{-b.r, -b.i, -b.j, -b.k} : b;
}

Matrix44 linearOf(const double R[3][3]) {
    Matrix44 m;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) m.m[row][c] = R[row][c];
    return m;
}

// The affine matrix T R S of Gram-Schmidt parts blended at fraction f: Embree's quaternion motion.
Matrix44 blend(const TransformParts& a, const TransformParts& b, double f) {
    double R[3][3];
    rotationOf(slerp(a.rotation, b.rotation, f), R);
    Matrix44 m;
    for (int row = 0; row < 3; ++row) {
        for (int c = 0; c < 3; ++c) {
            double s = 0;
            for (int k = 0; k <= c; ++k) s += R[row][k] * ((1 - f) * a.stretch[k][c] + f * b.stretch[k][c]);
            m.m[row][c] = s;
        }
        m.m[row][3] = (1 - f) * a.translation[row] + f * b.translation[row];
    }
    return m;
}

// pbrt's split of an affine matrix, M = T R P with P symmetric.
struct PolarParts {
    double translation[3];
    Quaternion rotation;
    Matrix44 stretch;  // P, linear part only
};

// R is the limit of Newton's iteration R <- (R + R^-T) / 2 from the linear part L (quadratic
// convergence). A mirror (det L < 0) is carried by P as -P, R being the rotation of -L.
PolarParts polarOf(const Matrix44& m) {
    Matrix44 L;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) L.m[row][c] = m.m[row][c];
    const auto& a = L.m;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    const double sign = det < 0 ? -1 : 1;
    Matrix44 R = L;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) R.m[row][c] *= sign;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const Matrix44 inverseTranspose = transpose(inverse(R));
        double change = 0;
        for (int row = 0; row < 3; ++row)
            for (int c = 0; c < 3; ++c) {
                const double next = (R.m[row][c] + inverseTranspose.m[row][c]) / 2;
                change = std::max(change, std::fabs(next - R.m[row][c]));
                R.m[row][c] = next;
            }
        if (change < 1e-15) break;
    }
    PolarParts p;
    for (int row = 0; row < 3; ++row) p.translation[row] = m.m[row][3];
    double r[3][3];
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) r[row][c] = R.m[row][c];
    p.rotation = quaternionOf(r);
    p.stretch = transpose(R) * L;
    return p;
}

// pbrt's motion at fraction f: T and P blended linearly, R spherically (b's rotation already on
// a's side).
Matrix44 polarBlend(const PolarParts& a, const PolarParts& b, double f) {
    double R[3][3];
    rotationOf(slerp(a.rotation, b.rotation, f), R);
    Matrix44 P;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) P.m[row][c] = (1 - f) * a.stretch.m[row][c] + f * b.stretch.m[row][c];
    Matrix44 m = linearOf(R) * P;
    for (int row = 0; row < 3; ++row) m.m[row][3] = (1 - f) * a.translation[row] + f * b.translation[row];
    return m;
}

bool nearlySame(const Matrix44& a, const Matrix44& b) {
    double size = 0, difference = 0;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 4; ++c) {
            size = std::max(size, std::fabs(a.m[row][c]));
            difference = std::max(difference, std::fabs(a.m[row][c] - b.m[row][c]));
        }
    return difference <= 1e-9 * (1 + size);
}

}  // namespace

AnimatedTransform::AnimatedTransform(const Transform& start, const Transform& end)
    : start_(start), end_(end), moves_(!sameMatrix(start.forward, end.forward)) {
    if (!moves_) return;
    TransformParts a = partsOf(start.forward), b = partsOf(end.forward);
    b.rotation = nearSide(a.rotation, b.rotation);
    PolarParts pa = polarOf(start.forward), pb = polarOf(end.forward);
    pb.rotation = nearSide(pa.rotation, pb.rotation);
    bool same = true;
    for (const double f : {0.25, 0.5, 0.75}) same = same && nearlySame(blend(a, b, f), polarBlend(pa, pb, f));
    if (same) {
        steps_ = {a, b};
        return;
    }
    steps_.push_back(a);
    for (int i = 1; i <= kMotionSteps; ++i) {
        TransformParts p = i == kMotionSteps ? b : partsOf(polarBlend(pa, pb, double(i) / kMotionSteps));
        p.rotation = nearSide(steps_.back().rotation, p.rotation);
        steps_.push_back(p);
    }
}

Transform AnimatedTransform::at(float time) const {
    if (!moves_ || time <= 0) return start_;
    if (time >= 1) return end_;
    // The step and the fraction within it, in float as Embree finds them.
    const float segments = float(steps_.size() - 1), scaled = time * segments;
    const float index = std::clamp(std::floor(scaled), 0.0f, segments - 1);
    return makeTransform(blend(steps_[std::size_t(index)], steps_[std::size_t(index) + 1], scaled - index));
}

}  // namespace lenslab
