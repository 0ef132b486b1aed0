#include "RayBatch.h"

#include <algorithm>

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

namespace {

// One surface for every ray. Rays are independent (ivdep) and the step uses selects instead of
// branches, so this loop vectorises.
void stepAll(std::size_t count, double* px, double* py, double* pz, double* vx, double* vy, double* vz,
             std::uint8_t* why, std::int16_t* at, const Surface& s, double eta, std::int16_t index) {
    const double zVertex = s.z, curvature = s.curvature, radius = 1.0 / curvature;
    const double r2 = s.apertureRadius * s.apertureRadius;
    const bool isStop = s.isStop;
#pragma GCC ivdep
    for (std::size_t r = 0; r < count; ++r) {
        double x = px[r], y = py[r], z = pz[r], u = vx[r], v = vy[r], w = vz[r];
        const auto b = static_cast<std::uint8_t>(stepThroughSurface(x, y, z, u, v, w, zVertex, curvature, radius, r2, eta, isStop));
        const bool alive = why[r] == 0;
        px[r] = alive ? x : px[r];
        py[r] = alive ? y : py[r];
        pz[r] = alive ? z : pz[r];
        vx[r] = alive ? u : vx[r];
        vy[r] = alive ? v : vy[r];
        vz[r] = alive ? w : vz[r];
        const bool stops = alive & (b != 0);
        why[r] = stops ? b : why[r];
        at[r] = stops ? index : at[r];
    }
}

}  // namespace

void traceBatch(const LensSystem& lens, RayBatch& batch, TraceDirection direction) {
    const int n = static_cast<int>(lens.surfaces.size());
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    std::fill(batch.blocked.begin(), batch.blocked.end(), BlockReason::None);
    std::fill(batch.blockedAt.begin(), batch.blockedAt.end(), std::int16_t(-1));
    static_assert(sizeof(BlockReason) == 1 && static_cast<int>(BlockReason::None) == 0);
    // Surface-major order: each surface's constants stay in registers across the ray loop.
    for (int k = 0; k < n; ++k) {
        const int i = toFilm ? k : n - 1 - k;
        const Surface& s = lens.surfaces[i];
        const double nScene = lens.indexBefore(i), nFilm = s.indexAfter;
        stepAll(batch.size(), batch.ox.data(), batch.oy.data(), batch.oz.data(), batch.dx.data(), batch.dy.data(),
                batch.dz.data(), reinterpret_cast<std::uint8_t*>(batch.blocked.data()), batch.blockedAt.data(), s,
                toFilm ? nScene / nFilm : nFilm / nScene, static_cast<std::int16_t>(i));
    }
}

}  // namespace lenslab
