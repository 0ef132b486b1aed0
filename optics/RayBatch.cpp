#include "RayBatch.h"

namespace lenslab {

void RayBatch::resize(std::size_t n) {
    for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz}) v->resize(n);
    blocked.resize(n);
    blockedAt.resize(n);
}

void RayBatch::set(std::size_t i, const Ray& r) {
    ox[i] = r.origin.x; oy[i] = r.origin.y; oz[i] = r.origin.z;
    dx[i] = r.direction.x; dy[i] = r.direction.y; dz[i] = r.direction.z;
}

Ray RayBatch::get(std::size_t i) const {
    return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}};
}

void traceBatch(const LensSystem& lens, RayBatch& batch, TraceDirection direction) {
    const std::size_t count = batch.size();
    const int n = static_cast<int>(lens.surfaces.size());
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    double* __restrict px = batch.ox.data();
    double* __restrict py = batch.oy.data();
    double* __restrict pz = batch.oz.data();
    double* __restrict vx = batch.dx.data();
    double* __restrict vy = batch.dy.data();
    double* __restrict vz = batch.dz.data();
    BlockReason* __restrict why = batch.blocked.data();
    std::int16_t* __restrict at = batch.blockedAt.data();
    for (std::size_t r = 0; r < count; ++r) {
        why[r] = BlockReason::None;
        at[r] = -1;
    }
    // Surface-major order: each surface's constants stay in registers across the ray loop.
    for (int k = 0; k < n; ++k) {
        const int i = toFilm ? k : n - 1 - k;
        const Surface& s = lens.surfaces[i];
        const double nScene = lens.indexBefore(i), nFilm = s.indexAfter;
        const double eta = toFilm ? nScene / nFilm : nFilm / nScene;
        const double r2 = s.apertureRadius * s.apertureRadius;
        for (std::size_t r = 0; r < count; ++r) {
            if (why[r] != BlockReason::None) continue;
            const BlockReason b = stepThroughSurface(px[r], py[r], pz[r], vx[r], vy[r], vz[r], s.z,
                                                     s.curvature, r2, eta, s.isStop);
            if (b != BlockReason::None) {
                why[r] = b;
                at[r] = static_cast<std::int16_t>(i);
            }
        }
    }
}

}  // namespace lenslab
