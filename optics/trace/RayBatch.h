#pragma once
// Many rays traced at once, stored as structure-of-arrays so the surface loop vectorises.
#include <cstdint>
#include <vector>

#include "trace/ExactTrace.h"

namespace lenslab {

struct RayBatch {
    std::vector<double> ox, oy, oz;  // origins (mm, lens space)
    std::vector<double> dx, dy, dz;  // unit directions
    std::vector<BlockReason> blocked;  // filled by traceBatch
    std::vector<std::int16_t> blockedAt;  // blocking surface index, -1 when the ray passed

    void resize(std::size_t n);
    std::size_t size() const { return ox.size(); }
    void set(std::size_t i, const Ray& r);
    Ray get(std::size_t i) const;
};

// Traces every ray of the batch through the whole lens in place (coordinates as traceRay's). Blocked
// rays keep the state they had in front of the surface that stopped them, in that surface's frame.
void traceBatch(const LensSystem& lens, RayBatch& batch, TraceDirection direction);

struct WavelengthEtas;
// The same with each ray at its own wavelength: ray r refracts with the ratios of band bands[r] of
// `etas` (tabulated for this lens and direction), bit for bit the trace of atWavelength(lens, that
// band's centre).
void traceBatch(const LensSystem& lens, RayBatch& batch, TraceDirection direction, const WavelengthEtas& etas,
                const std::uint16_t* bands);

}  // namespace lenslab
