#include "prescription/FrameChange.h"

#include <cmath>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

using Matrix = std::array<double, 9>;

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return c;
}

Matrix transposed(const Matrix& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

// Right-handed rotations about the lens axes by an angle in degrees. Exact for multiples of 90
// degrees, so that a fold and its unfolding cancel to the bit.
void sinCos(double degrees, double& s, double& c) {
    const double quarter = degrees / 90;
    if (quarter == std::floor(quarter)) {
        static const double kS[4] = {0, 1, 0, -1}, kC[4] = {1, 0, -1, 0};
        const int q = ((static_cast<long long>(quarter) % 4) + 4) % 4;
        s = kS[q];
        c = kC[q];
        return;
    }
    s = std::sin(degrees * kPi / 180);
    c = std::cos(degrees * kPi / 180);
}
Matrix aboutX(double degrees) {
    double s, c;
    sinCos(degrees, s, c);
    return {1, 0, 0, 0, c, -s, 0, s, c};
}
Matrix aboutY(double degrees) {
    double s, c;
    sinCos(degrees, s, c);
    return {c, 0, s, 0, 1, 0, -s, 0, c};
}
Matrix aboutZ(double degrees) {
    double s, c;
    sinCos(degrees, s, c);
    return {c, -s, 0, s, c, 0, 0, 0, 1};
}

std::array<double, 3> times(const Matrix& m, const std::array<double, 3>& v) {
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

// p' = R (p - pivot) + pivot + offset.
RigidMotion about(const Matrix& r, double pivotZ, const std::array<double, 3>& offset) {
    RigidMotion m;
    m.rotation = r;
    const auto turned = times(r, {0, 0, pivotZ});
    m.shift = {offset[0] - turned[0], offset[1] - turned[1], pivotZ + offset[2] - turned[2]};
    return m;
}

}  // namespace

RigidMotion RigidMotion::then(const RigidMotion& next) const {
    RigidMotion m;
    m.rotation = multiply(next.rotation, rotation);
    const auto t = times(next.rotation, shift);
    m.shift = {t[0] + next.shift[0], t[1] + next.shift[1], t[2] + next.shift[2]};
    return m;
}

RigidMotion RigidMotion::inverse() const {
    RigidMotion m;
    m.rotation = transposed(rotation);  // orthogonal, mirrored or not
    const auto t = times(m.rotation, shift);
    m.shift = {-t[0], -t[1], -t[2]};
    return m;
}

std::array<double, 3> RigidMotion::applyToPoint(const std::array<double, 3>& p) const {
    const auto t = times(rotation, p);
    return {t[0] + shift[0], t[1] + shift[1], t[2] + shift[2]};
}

std::array<double, 3> RigidMotion::applyToDirection(const std::array<double, 3>& d) const { return times(rotation, d); }

// In the file's axes (z along the light) a surface decentred by d and tilted by R has its vertex at
// d and its axes turned by R = Rx(-alpha) Ry(-beta) Rz(gamma) (Code V's alpha and beta turn the
// other way from a right-handed rotation). Lens space mirrors z (M = diag(1, 1, -1)), which turns R
// into M R M = Rx(alpha) Ry(beta) Rz(gamma) and d into (dx, dy, -dz). A point's coordinates in the
// surface's frame are then R^T (p - v - d) + v about the vertex v = (0, 0, vertexZ); with Zemax's
// order flag 1 the tilts come first (Rz Ry Rx) and the decentre runs along the turned axes.
SurfaceMotions surfaceMotions(const FrameChange& change, double vertexZ) {
    const auto& a = change.tiltDegrees;
    const Matrix r = change.order == TiltOrder::DecentreThenTilt
                         ? multiply(aboutX(a[0]), multiply(aboutY(a[1]), aboutZ(a[2])))
                         : multiply(aboutZ(a[2]), multiply(aboutY(a[1]), aboutX(a[0])));
    std::array<double, 3> d = {change.decentre[0], change.decentre[1], -change.decentre[2]};
    if (change.order == TiltOrder::TiltThenDecentre) d = times(r, d);
    // Surface frame -> arriving coordinates: p = R q' + v + d (q' about the vertex); its inverse:
    const RigidMotion intoSurface = about(r, vertexZ, d).inverse();
    SurfaceMotions m;
    switch (change.mode) {
        case FrameMode::Basic: m.before = intoSurface; break;
        case FrameMode::DecentreAndReturn:
            m.before = intoSurface;
            m.after = intoSurface.inverse();
            break;
        case FrameMode::Bend:
            m.before = intoSurface;
            m.after = about(transposed(r), vertexZ, {0, 0, 0});
            break;
        case FrameMode::Reverse: m.after = intoSurface.inverse(); break;
    }
    return m;
}

}  // namespace lenslab
