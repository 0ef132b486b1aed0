// libFuzzer target: bytes decoded into a small lens the parser would accept (1-8 surfaces, radii
// from 1e-3 mm to 1e9 mm or flat, a third of the curved ones conics with even-asphere terms, stops
// from 1 um) plus an f-number, a focus distance and up to 16
// rays, then analyzeLens, traceRay (double and float), traceBatch and traceThick. Refusals must be
// LensTableError / OpticsError; a ray that passes must come out finite and unit length, a blocked
// ray must carry its reason and surface; the batch must agree with the scalar trace.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <vector>

#include "FuzzCheck.h"
#include "trace/ExactTrace.h"
#include "settings/LensAnalysis.h"
#include "prescription/OpticsError.h"
#include "trace/RayBatch.h"

using namespace lenslab;
using lenslab::fuzz::check;

namespace {

// Log-uniform in [lo, hi]: the extremes are as likely as the everyday values.
double logUniform(FuzzedDataProvider& in, double lo, double hi) {
    return lo * std::pow(hi / lo, in.ConsumeProbability<double>());
}

double uniform(FuzzedDataProvider& in, double lo, double hi) {
    return lo + (hi - lo) * in.ConsumeProbability<double>();
}

LensTable decodeTable(FuzzedDataProvider& in) {
    LensTable t;
    t.name = "fuzz.dat";
    t.layout = TableLayout::GapBefore;
    const int n = in.ConsumeIntegralInRange(1, 8);
    const int stop = in.ConsumeIntegralInRange(0, n - 1);
    for (int i = 0; i < n; ++i) {
        LensTableRow r;
        r.line = i + 1;
        r.gap = i == 0 || in.ConsumeIntegralInRange(0, 7) == 0 ? 0.0 : logUniform(in, 1e-3, 100);
        if (i == stop) {
            r.stop = true;
            r.diameter = logUniform(in, 1e-3, 200);
        } else {
            const bool flat = in.ConsumeIntegralInRange(0, 4) == 0;
            r.radius = flat ? 0.0 : (in.ConsumeBool() ? 1 : -1) * logUniform(in, 1e-3, 1e9);
            r.index = i + 1 == n || in.ConsumeBool() ? 1.0 : uniform(in, 1.0, 3.0);
            r.diameter = flat ? logUniform(in, 1e-3, 200)
                              : std::min(2 * std::fabs(r.radius), 200.0) * uniform(in, 1e-3, 1.0);
            // One curved surface in three becomes a conic, with even-asphere terms of a size that
            // bends the profile by up to about its own sag at the rim.
            if (!flat && in.ConsumeIntegralInRange(0, 2) == 0) {
                const double R = std::fabs(r.radius);
                r.conic = uniform(in, -5, 2);
                r.aspheric[1] = uniform(in, -1, 1) * 1e-1 / (R * R * R);
                r.aspheric[2] = uniform(in, -1, 1) * 1e-2 / (R * R * R * R * R);
            }
        }
        t.rows.push_back(r);
    }
    return t;
}

Ray decodeRay(FuzzedDataProvider& in, const LensSystem& lens, TraceDirection direction) {
    double reach = 0;
    for (const Surface& s : lens.surfaces) reach = std::max(reach, s.apertureRadius);
    reach *= 1.2;
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    const double z = toFilm ? lens.frontZ() + uniform(in, 0, 2 * reach + 10)
                            : lens.rearZ() - uniform(in, 0, 2 * reach + 10);
    Vec3 d{uniform(in, -1, 1), uniform(in, -1, 1), toFilm ? -uniform(in, 0, 1) : uniform(in, 0, 1)};
    if (in.ConsumeIntegralInRange(0, 3) == 0) d = {0, 0, toFilm ? -1.0 : 1.0};  // axial family
    if (!(length(d) > 1e-6)) d = {0, 0, toFilm ? -1.0 : 1.0};
    return {{uniform(in, -reach, reach), uniform(in, -reach, reach), z}, normalize(d)};
}

// unitTolerance: the hit point carries a relative error of about eps * curvature * distance travelled
// (the quadratic cancels that many digits). The surface step normalises its normal, so refraction
// stays unit length even then (before it did, a 1 um sphere met after 97 mm of glass left a double
// direction 2.6e-6 off); float keeps the looser promise of finiteness.
void checkTraced(const TraceResult& r, const LensSystem& lens, double unitTolerance) {
    const int surfaces = static_cast<int>(lens.surfaces.size());
    const bool ok = isFinite(r.ray.origin) && isFinite(r.ray.direction) &&
                    (r.ok() ? std::fabs(length(r.ray.direction) - 1) < unitTolerance
                            : r.surface >= 0 && r.surface < surfaces);
    if (!ok) {
        for (const Surface& s : lens.surfaces)
            std::fprintf(stderr, "surface z %.17g R %.17g n %.17g aperture %.17g\n", s.z, s.radius, s.indexAfter,
                         s.apertureRadius);
        std::fprintf(stderr, "ray (%.17g %.17g %.17g) (%.17g %.17g %.17g) %s at surface %d\n", r.ray.origin.x,
                     r.ray.origin.y, r.ray.origin.z, r.ray.direction.x, r.ray.direction.y, r.ray.direction.z,
                     blockReasonName(r.blocked), r.surface);
    }
    check(ok, "a passing ray is finite with a unit direction, a blocked one names its surface");
}

void checkAnalysis(const LensAnalysis& a) {
    const FirstOrder& fo = a.firstOrder;
    for (double v : {fo.efl, fo.eflFront, fo.zF, fo.zFPrime, fo.zP, fo.zPPrime, a.aperture.fstopMin,
                     a.aperture.fstopMax, a.aperture.stopDiameterMax, a.fstop, a.stopDiameter,
                     a.pupils.entrance.z, a.pupils.entrance.diameter, a.pupils.exit.z, a.pupils.exit.diameter,
                     a.focus.imageZThick, a.focus.imageZExact})
        check(std::isfinite(v), "every analysed value is finite");
    check(a.focus.raysUsed > 0, "a focus uses rays");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    LensSystem lens;
    try {
        lens = buildLensSystem(decodeTable(in));
    } catch (const LensTableError&) {
        return 0;  // e.g. overlapping surfaces: the parser's refusal, covered by fuzz_lens_table
    }
    const std::optional<double> fstop =
        in.ConsumeBool() ? std::nullopt : std::optional<double>(logUniform(in, 0.3, 3e4));
    const double focus = in.ConsumeBool() ? std::numeric_limits<double>::infinity() : logUniform(in, 1e-3, 1e7);
    std::optional<LensAnalysis> analysis;
    try {
        analysis = analyzeLens(lens, fstop, focus);
        checkAnalysis(*analysis);
    } catch (const OpticsError& e) {
        check(e.what()[0] != '\0', "a refusal says why");
    }

    const TraceDirection direction = in.ConsumeBool() ? TraceDirection::SceneToFilm : TraceDirection::FilmToScene;
    const int count = in.ConsumeIntegralInRange(1, 16);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) rays.push_back(decodeRay(in, lens, direction));
    RayBatch batch;
    batch.resize(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) batch.set(i, rays[i]);
    traceBatch(lens, batch, direction);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const TraceResult exact = traceRay(lens, rays[i], direction);
        checkTraced(exact, lens, 1e-12);
        checkTraced(traceRayT<float>(lens, rays[i], direction), lens, std::numeric_limits<double>::infinity());
        // One routine, no FP contraction in optics: the batch reproduces the scalar trace exactly.
        check(batch.blocked[i] == exact.blocked && batch.blockedAt[i] == exact.surface, "batch blocks like traceRay");
        const Ray b = batch.get(i);
        check(b.origin.x == exact.ray.origin.x && b.origin.y == exact.ray.origin.y &&
                  b.origin.z == exact.ray.origin.z && b.direction.z == exact.ray.direction.z,
              "batch lands like traceRay");
        if (analysis) {
            const TraceResult thick = traceThick(analysis->thick, rays[i], direction);
            if (thick.ok()) check(isFinite(thick.ray.origin) && isFinite(thick.ray.direction), "a thick-lens ray stays finite");
        }
    }
    return 0;
}
