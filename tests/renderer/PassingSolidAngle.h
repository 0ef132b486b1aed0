#pragma once
// The irradiance a uniform scene of radiance 1 gives a film point behind a lens, by brute force:
// the projected solid angle (integral of cos dw) of the directions from the point that pass the
// exact lens, counted over an m x m grid of cosine-weighted directions within halfAngle of normal.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "prescription/LensSystem.h"
#include "sampling/Sampling.h"
#include "trace/ExactTrace.h"

namespace lenslab::test {

inline double passingProjectedSolidAngle(const LensSystem& lens, const Vec3& from, const Vec3& normal, double halfAngle,
                                         int m) {
    // An orthonormal frame around the normal.
    const Vec3 e1 = normalize(Vec3{normal.z, 0, -normal.x});
    const Vec3 e2{normal.y * e1.z - normal.z * e1.y, normal.z * e1.x - normal.x * e1.z, normal.x * e1.y - normal.y * e1.x};
    const double sinMax = std::sin(halfAngle);
    RayBatch batch;
    batch.resize(std::size_t(m) * m);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            float dx, dy;
            concentricDisk(float((i + 0.5) / m), float((j + 0.5) / m), dx, dy);
            const double x = sinMax * dx, y = sinMax * dy, z = std::sqrt(std::max(0.0, 1 - x * x - y * y));
            batch.set(std::size_t(j) * m + i, {from, x * e1 + y * e2 + z * normal});
        }
    traceBatch(lens, batch, TraceDirection::FilmToScene);
    const std::size_t passed = std::count(batch.blocked.begin(), batch.blocked.end(), BlockReason::None);
    return M_PI * sinMax * sinMax * double(passed) / (double(m) * m);
}

}  // namespace lenslab::test
