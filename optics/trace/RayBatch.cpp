#include "trace/RayBatch.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "trace/WavelengthEtas.h"

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

// Keeps the batch's state for rays that passed this surface and records the block of those it stopped.
struct BatchArrays {
    double *px, *py, *pz, *vx, *vy, *vz;
    std::uint8_t* why;
    std::int16_t* at;
};

inline void keep(const BatchArrays& a, std::size_t r, double x, double y, double z, double u, double v, double w,
                 BlockReason b, std::int16_t index) {
    const bool alive = a.why[r] == 0;
    a.px[r] = alive ? x : a.px[r];
    a.py[r] = alive ? y : a.py[r];
    a.pz[r] = alive ? z : a.pz[r];
    a.vx[r] = alive ? u : a.vx[r];
    a.vy[r] = alive ? v : a.vy[r];
    a.vz[r] = alive ? w : a.vz[r];
    const auto code = static_cast<std::uint8_t>(b);
    const bool stops = alive & (code != 0);
    a.why[r] = stops ? code : a.why[r];
    a.at[r] = stops ? index : a.at[r];
}

// The index ratio each ray refracts with: the surface's own, or the ray's wavelength band's.
struct SurfaceEta {
    double eta;
    double operator()(std::size_t) const { return eta; }
};
struct BandEtas {
    const double* etaOfBand;  // this surface's row of WavelengthEtas
    const std::uint16_t* band;
    double operator()(std::size_t r) const { return etaOfBand[band[r]]; }
};

// One quadric surface for every ray. Rays are independent (ivdep) and the step uses selects instead
// of branches, so this loop vectorises (GCC's -fopt-info-vec says so; SurfaceStep.h keeps the
// constants the selects read numbers, not bytes, for it).
template <bool kConic, class EtaOf>
void stepQuadric(std::size_t count, const BatchArrays& a, const SurfaceConstants<double>& s, EtaOf etaOf,
                 std::int16_t index) {
#pragma GCC ivdep
    for (std::size_t r = 0; r < count; ++r) {
        double x = a.px[r], y = a.py[r], z = a.pz[r], u = a.vx[r], v = a.vy[r], w = a.vz[r];
        const BlockReason b = stepThroughQuadric<double, kConic>(x, y, z, u, v, w, s, etaOf(r));
        keep(a, r, x, y, z, u, v, w, b, index);
    }
}

// One asphere for every ray: Newton's passes run over the whole batch (each vectorises), a ray's t
// frozen once its own step converged, so every ray sees exactly the scalar trace's iterations.
template <class EtaOf>
void stepAsphere(std::size_t count, const BatchArrays& a, const SurfaceConstants<double>& s, EtaOf etaOf,
                 std::int16_t index) {
    thread_local std::vector<double> t;
    thread_local std::vector<std::uint8_t> done;
    thread_local std::vector<std::uint32_t> stragglers;
    t.resize(count);
    done.assign(count, 0);
    double* tt = t.data();
    std::uint8_t* dn = done.data();
    // A ray blocked at an earlier surface takes no part: it would only keep the passes going (rays far
    // outside the lens, as the exit-pupil search traces by the thousand, rarely converge).
    std::size_t open = 0;
#pragma GCC ivdep
    for (std::size_t r = 0; r < count; ++r) {
        tt[r] = asphereStart(a.px[r], a.py[r], a.pz[r] - s.zVertex, a.vx[r], a.vy[r], a.vz[r], s);
        dn[r] = a.why[r] != 0 || !std::isfinite(tt[r]);
        open += dn[r] == 0;
    }
    // One Newton step of ray r unless it is done: converged (2), or stalled on a non-finite t (1,
    // which finishAsphere reports as a miss).
    const auto advance = [&](std::size_t r) {
        const double step = asphereNewtonStep(a.px[r], a.py[r], a.pz[r] - s.zVertex, a.vx[r], a.vy[r], a.vz[r], tt[r], EvenSag<double>{s});
        const bool moving = dn[r] == 0;
        const double next = tt[r] + step;
        tt[r] = moving ? next : tt[r];
        const std::uint8_t state = asphereStepConverged(step, next) ? 2 : std::isfinite(next) ? 0 : 1;
        dn[r] = moving ? state : dn[r];
    };
    // Whole-batch passes while many rays iterate; the few that converge slowly or never (a ray that
    // misses the surface runs all the iterations) then go on alone, so that they do not cost a pass
    // over the whole batch each. Either way a ray takes exactly the scalar trace's steps.
    int pass = 0;
    for (; pass < kMaxAsphereIterations && open > count / 16; ++pass) {
        open = 0;
#pragma GCC ivdep
        for (std::size_t r = 0; r < count; ++r) {
            advance(r);
            open += dn[r] == 0;
        }
    }
    stragglers.clear();
    for (std::size_t r = 0; r < count && open > 0; ++r)
        if (dn[r] == 0) stragglers.push_back(std::uint32_t(r));
    for (; pass < kMaxAsphereIterations && !stragglers.empty(); ++pass) {
        std::size_t left = 0;
        for (std::uint32_t r : stragglers) {
            advance(r);
            if (dn[r] == 0) stragglers[left++] = r;
        }
        stragglers.resize(left);
    }
#pragma GCC ivdep
    for (std::size_t r = 0; r < count; ++r) {
        double x = a.px[r], y = a.py[r], z = a.pz[r], u = a.vx[r], v = a.vy[r], w = a.vz[r];
        const BlockReason b = finishAsphere(x, y, z, u, v, w, tt[r], z - s.zVertex, dn[r] == 2, s, etaOf(r), EvenSag<double>{s});
        keep(a, r, x, y, z, u, v, w, b, index);
    }
}

// A surface the general step takes (a form beyond the even asphere, a shaped aperture), ray by ray.
template <class EtaOf>
void stepGeneral(std::size_t count, const BatchArrays& a, const SurfaceConstants<double>& s,
                 const GeneralSurface<double>& g, EtaOf etaOf, std::int16_t index) {
    for (std::size_t r = 0; r < count; ++r) {
        if (a.why[r] != 0) continue;
        double x = a.px[r], y = a.py[r], z = a.pz[r], u = a.vx[r], v = a.vy[r], w = a.vz[r];
        const BlockReason b = stepThroughGeneral<double>(x, y, z, u, v, w, s, g, etaOf(r));
        keep(a, r, x, y, z, u, v, w, b, index);
    }
}

// A decentre or tilt: the coordinates of every ray still travelling move with it.
void moveRays(std::size_t count, const BatchArrays& a, const RigidMotion& m) {
    if (m.isIdentity()) return;
    const auto& q = m.rotation;
    const auto& t = m.shift;
#pragma GCC ivdep
    for (std::size_t r = 0; r < count; ++r) {
        const bool alive = a.why[r] == 0;
        const double x = a.px[r], y = a.py[r], z = a.pz[r], u = a.vx[r], v = a.vy[r], w = a.vz[r];
        a.px[r] = alive ? q[0] * x + q[1] * y + q[2] * z + t[0] : x;
        a.py[r] = alive ? q[3] * x + q[4] * y + q[5] * z + t[1] : y;
        a.pz[r] = alive ? q[6] * x + q[7] * y + q[8] * z + t[2] : z;
        a.vx[r] = alive ? q[0] * u + q[1] * v + q[2] * w : u;
        a.vy[r] = alive ? q[3] * u + q[4] * v + q[5] * w : v;
        a.vz[r] = alive ? q[6] * u + q[7] * v + q[8] * w : w;
    }
}

// Both traces: etaOfSurface(i, constants) gives surface i's ratio per ray.
template <class EtaOfSurface>
void traceBatchWith(const LensSystem& lens, RayBatch& batch, TraceDirection direction, EtaOfSurface etaOfSurface) {
    const int n = static_cast<int>(lens.surfaces.size());
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    std::fill(batch.blocked.begin(), batch.blocked.end(), BlockReason::None);
    std::fill(batch.blockedAt.begin(), batch.blockedAt.end(), std::int16_t(-1));
    static_assert(sizeof(BlockReason) == 1 && static_cast<int>(BlockReason::None) == 0);
    const BatchArrays arrays{batch.ox.data(), batch.oy.data(), batch.oz.data(), batch.dx.data(), batch.dy.data(),
                             batch.dz.data(), reinterpret_cast<std::uint8_t*>(batch.blocked.data()), batch.blockedAt.data()};
    // Surface-major order: each surface's constants stay in registers across the ray loop.
    for (int k = 0; k < n; ++k) {
        const int i = toFilm ? k : n - 1 - k;
        const Surface& surface = lens.surfaces[i];
        const SurfaceConstants<double> s = surfaceConstants<double>(lens, i, direction);
        const auto index = static_cast<std::int16_t>(i);
        const auto etaOf = etaOfSurface(i, s);
        moveRays(batch.size(), arrays, motionInto(surface, direction));
        if (isDummy(lens, i)) {
            moveRays(batch.size(), arrays, motionOutOf(surface, direction));
            continue;
        }
        if (takesGeneralStep(lens, surface))
            stepGeneral(batch.size(), arrays, s, generalSurface<double>(lens, surface), etaOf, index);
        else if (s.asphericTerms > 0) stepAsphere(batch.size(), arrays, s, etaOf, index);
        else if (s.conicFactor != 1) stepQuadric<true>(batch.size(), arrays, s, etaOf, index);
        else stepQuadric<false>(batch.size(), arrays, s, etaOf, index);
        moveRays(batch.size(), arrays, motionOutOf(surface, direction));
    }
}

}  // namespace

void traceBatch(const LensSystem& lens, RayBatch& batch, TraceDirection direction) {
    traceBatchWith(lens, batch, direction, [](int, const SurfaceConstants<double>& s) { return SurfaceEta{s.eta}; });
}

void traceBatch(const LensSystem& lens, RayBatch& batch, TraceDirection direction, const WavelengthEtas& etas,
                const std::uint16_t* bands) {
    traceBatchWith(lens, batch, direction,
                   [&](int i, const SurfaceConstants<double>&) { return BandEtas{etas.etasOf(i), bands}; });
}

}  // namespace lenslab
