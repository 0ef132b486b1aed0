#pragma once
// Affine/projective 4x4 transforms in double precision, with their inverses, following the
// pbrt-v3 scene conventions (the current transform post-multiplies, LookAt gives world-to-camera).
#include "core/Vec3f.h"

namespace lenslab {

struct Matrix44 {
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
};

Matrix44 operator*(const Matrix44& a, const Matrix44& b);
Matrix44 transpose(const Matrix44& a);
// Throws std::domain_error for a singular matrix.
Matrix44 inverse(const Matrix44& a);

struct Transform {
    Matrix44 forward, backward;  // backward = inverse(forward)
};

Transform makeTransform(const Matrix44& m);  // computes the inverse
Transform operator*(const Transform& a, const Transform& b);
Transform inverse(const Transform& t);

Transform translate(double x, double y, double z);
Transform scale(double x, double y, double z);
Transform rotate(double degrees, double ax, double ay, double az);
Transform lookAt(const double eye[3], const double look[3], const double up[3]);

Vec3f transformPoint(const Transform& t, Vec3f p);
Vec3f transformVector(const Transform& t, Vec3f v);
Vec3f transformNormal(const Transform& t, Vec3f n);  // by the inverse transpose
// The partial dn of the unit normal n carried through t: that of normalize(transformNormal(t, n)).
// pbrt-v3 stops at transformNormal(t, dn), which is the same only under rotations and translations.
Vec3f transformNormalPartial(const Transform& t, Vec3f n, Vec3f dn);
bool swapsHandedness(const Transform& t);

}  // namespace lenslab
