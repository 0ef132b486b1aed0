#include "core/Transform.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace lenslab {

Matrix44 operator*(const Matrix44& a, const Matrix44& b) {
    Matrix44 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Matrix44 transpose(const Matrix44& a) {
    Matrix44 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

Matrix44 inverse(const Matrix44& a) {
    // Gauss-Jordan elimination with partial pivoting.
    double m[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            m[i][j] = a.m[i][j];
            m[i][j + 4] = i == j ? 1.0 : 0.0;
        }
    for (int c = 0; c < 4; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(m[r][c]) > std::fabs(m[pivot][c])) pivot = r;
        if (!(std::fabs(m[pivot][c]) > 1e-300)) throw std::domain_error("singular transform");
        if (pivot != c)
            for (int j = 0; j < 8; ++j) std::swap(m[c][j], m[pivot][j]);
        const double inv = 1.0 / m[c][c];
        for (int j = 0; j < 8; ++j) m[c][j] *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == c || m[r][c] == 0) continue;
            const double f = m[r][c];
            for (int j = 0; j < 8; ++j) m[r][j] -= f * m[c][j];
        }
    }
    Matrix44 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[i][j + 4];
    return r;
}

Transform makeTransform(const Matrix44& m) { return {m, inverse(m)}; }

Transform operator*(const Transform& a, const Transform& b) {
    return {a.forward * b.forward, b.backward * a.backward};
}

Transform inverse(const Transform& t) { return {t.backward, t.forward}; }

Transform translate(double x, double y, double z) {
    Transform t;
    t.forward.m[0][3] = x; t.forward.m[1][3] = y; t.forward.m[2][3] = z;
    t.backward.m[0][3] = -x; t.backward.m[1][3] = -y; t.backward.m[2][3] = -z;
    return t;
}

Transform scale(double x, double y, double z) {
    Matrix44 m;
    m.m[0][0] = x; m.m[1][1] = y; m.m[2][2] = z;
    return makeTransform(m);
}

Transform rotate(double degrees, double ax, double ay, double az) {
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    if (!(len > 0)) throw std::domain_error("rotation axis is zero");
    ax /= len; ay /= len; az /= len;
    const double theta = degrees * M_PI / 180.0, s = std::sin(theta), c = std::cos(theta);
    Matrix44 m;
    m.m[0][0] = ax * ax + (1 - ax * ax) * c;
    m.m[0][1] = ax * ay * (1 - c) - az * s;
    m.m[0][2] = ax * az * (1 - c) + ay * s;
    m.m[1][0] = ax * ay * (1 - c) + az * s;
    m.m[1][1] = ay * ay + (1 - ay * ay) * c;
    m.m[1][2] = ay * az * (1 - c) - ax * s;
    m.m[2][0] = ax * az * (1 - c) - ay * s;
    m.m[2][1] = ay * az * (1 - c) + ax * s;
    m.m[2][2] = az * az + (1 - az * az) * c;
    return {m, transpose(m)};
}

namespace {
void normalize3(double v[3]) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(l > 0)) throw std::domain_error("LookAt: degenerate direction");
    for (int i = 0; i < 3; ++i) v[i] /= l;
}
void cross3(const double a[3], const double b[3], double r[3]) {
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}
}  // namespace

Transform lookAt(const double eye[3], const double look[3], const double up[3]) {
    // Camera space (pbrt): +z toward `look`, +y up, +x = up x dir (left-handed).
    double dir[3] = {look[0] - eye[0], look[1] - eye[1], look[2] - eye[2]};
    normalize3(dir);
    double u[3] = {up[0], up[1], up[2]};
    normalize3(u);
    double right[3];
    cross3(u, dir, right);
    const double rl = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
    if (!(rl > 1e-9)) throw std::domain_error("LookAt: up vector is parallel to the viewing direction");
    for (double& v : right) v /= rl;
    double newUp[3];
    cross3(dir, right, newUp);
    Matrix44 cameraToWorld;
    for (int i = 0; i < 3; ++i) {
        cameraToWorld.m[i][0] = right[i];
        cameraToWorld.m[i][1] = newUp[i];
        cameraToWorld.m[i][2] = dir[i];
        cameraToWorld.m[i][3] = eye[i];
    }
    return inverse(makeTransform(cameraToWorld));
}

Vec3f transformPoint(const Transform& t, Vec3f p) {
    const auto& m = t.forward.m;
    const double x = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3];
    const double y = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3];
    const double z = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3];
    const double w = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
    return {float(x / w), float(y / w), float(z / w)};
}

Vec3f transformVector(const Transform& t, Vec3f v) {
    const auto& m = t.forward.m;
    return {float(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z),
            float(m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z),
            float(m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z)};
}

Vec3f transformNormal(const Transform& t, Vec3f n) {
    const auto& m = t.backward.m;
    return {float(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z),
            float(m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z),
            float(m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z)};
}

Vec3f transformNormalPartial(const Transform& t, Vec3f n, Vec3f dn) {
    const Vec3f g = transformNormal(t, n), dg = transformNormal(t, dn);
    const float len = length(g);
    if (!(len > 0)) return {};
    const Vec3f unit = g / len;
    return (dg - dot(unit, dg) * unit) / len;
}

bool swapsHandedness(const Transform& t) {
    const auto& m = t.forward.m;
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return det < 0;
}

}  // namespace lenslab
