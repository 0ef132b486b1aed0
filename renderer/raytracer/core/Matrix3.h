#pragma once
// 3 x 3 matrices in double precision, row-major, for the film's colour transforms.
#include <array>
#include <optional>

namespace lenslab {

using Matrix3 = std::array<double, 9>;
using Triple = std::array<double, 3>;

inline Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
    Matrix3 c{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) c[r * 3 + j] += a[r * 3 + k] * b[k * 3 + j];
    return c;
}

inline Triple applyMatrix(const Matrix3& m, const Triple& v) {
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

inline Matrix3 transpose(const Matrix3& m) { return {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]}; }

// The inverse by cofactors; none when the matrix is singular.
inline std::optional<Matrix3> inverse(const Matrix3& m) {
    const Matrix3 cof = {m[4] * m[8] - m[5] * m[7], m[5] * m[6] - m[3] * m[8], m[3] * m[7] - m[4] * m[6],
                         m[2] * m[7] - m[1] * m[8], m[0] * m[8] - m[2] * m[6], m[1] * m[6] - m[0] * m[7],
                         m[1] * m[5] - m[2] * m[4], m[2] * m[3] - m[0] * m[5], m[0] * m[4] - m[1] * m[3]};
    const double det = m[0] * cof[0] + m[1] * cof[1] + m[2] * cof[2];
    if (!(det != 0)) return std::nullopt;
    Matrix3 inv = transpose(cof);
    for (double& v : inv) v /= det;
    return inv;
}

}  // namespace lenslab
