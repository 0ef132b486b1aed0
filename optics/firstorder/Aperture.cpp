#include "firstorder/Aperture.h"

#include "prescription/NumberText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "trace/ExactTrace.h"
#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

Ray marginalRayFromFPrime(const FirstOrder& fo, double sinTheta) {
    return {{0, 0, fo.zFPrime}, {0, sinTheta, std::sqrt(1.0 - sinTheta * sinTheta)}};
}

// Whether the cone of half-angle theta from F' passes the whole lens (stop at table size). A central
// obscuration takes out the middle of the cone, not its rim: it sets no f-number.
bool conePasses(const LensSystem& lens, const FirstOrder& fo, double sinTheta, bool stopOnly) {
    TraceOptions options;
    options.ignoreObscurations = true;
    options.stopApertureOnly = stopOnly;
    return traceRay(lens, marginalRayFromFPrime(fo, sinTheta), TraceDirection::FilmToScene, options).ok();
}

// How far from the stop's centre the marginal ray traced from F' through the surfaces behind the
// stop meets the stop's surface, where its aperture clips (a curved stop, on the rear face of a
// Cooke triplet's flint, is met off its vertex plane: measured there, its opening read 0.3% small),
// in the stop's own frame: a decentred stop's centre is off the axis of the coordinates arriving at
// it. Where the ray misses the surface, its height on the vertex plane.
double stopHeight(const LensSystem& lens, const FirstOrder& fo, double sinTheta, bool stopOnly, bool* blocked) {
    TraceOptions options;
    options.begin = lens.stopIndex + 1;
    options.ignoreObscurations = true;
    options.stopApertureOnly = stopOnly;
    const TraceResult r = traceRay(lens, marginalRayFromFPrime(fo, sinTheta), TraceDirection::FilmToScene, options);
    *blocked = !r.ok();
    const RigidMotion into = motionInto(lens.stop(), TraceDirection::FilmToScene);
    const Ray inStop = movedRay(into, r.ray);
    const auto onPlane = [&] {
        const double t = (lens.stop().z - inStop.origin.z) / inStop.direction.z;
        return std::hypot(inStop.origin.x + t * inStop.direction.x, inStop.origin.y + t * inStop.direction.y);
    };
    const Surface& stop = lens.stop();
    if (stop.curvature == 0 && !stop.isAspheric() && stop.form.isEvenAsphere()) return onPlane();
    TraceOptions onStop;
    onStop.begin = lens.stopIndex;
    onStop.end = lens.stopIndex + 1;
    onStop.ignoreApertures = true;
    std::vector<Vec3> path;
    onStop.path = &path;
    traceRay(lens, r.ray, TraceDirection::FilmToScene, onStop);
    if (path.size() < 2) return onPlane();
    const auto p = into.applyToPoint({path[1].x, path[1].y, path[1].z});
    return std::hypot(p[0], p[1]);
}

// The narrowest f-number at which some light still passes on axis. A central obscuration (a reflex
// lens's secondary mirror, a hole in its primary) blocks the middle of every cone from F', so a
// stop closed into its shadow passes nothing: the rim ray of the cone, traced with the
// obscurations, must pass. Cones from sinWidest down pass until the shadow's edge; bisected there.
double narrowestPassingFstop(const LensSystem& lens, const FirstOrder& fo, double sinWidest) {
    const auto rimPasses = [&](double sinTheta) {
        return traceRay(lens, marginalRayFromFPrime(fo, sinTheta), TraceDirection::FilmToScene).ok();
    };
    double lo = 1.0 / (2.0 * kNarrowestFstop), hi = sinWidest;
    if (lo >= hi || rimPasses(lo)) return kNarrowestFstop;
    if (!rimPasses(hi)) throw OpticsError("no ray from the rear focal point passes the lens's obscurations");
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (rimPasses(mid) ? hi : lo) = mid;
    }
    return 1.0 / (2.0 * hi);
}

// `v` at formatFNumber's digits, the last one rounded up or down (a range's end, toward its inside).
double atThreeDigits(double v, bool up) {
    if (!std::isfinite(v) || v <= 0) return v;
    const double unit = v >= 1000 ? 1 : std::pow(10.0, std::floor(std::log10(v)) - 2);
    const double steps = v / unit;
    // A value at three digits already keeps them (2.02 stays 2.02, not 2.03 by a rounding error).
    const double near = std::round(steps);
    return (std::fabs(steps - near) < 1e-9 * steps ? near : up ? std::ceil(steps) : std::floor(steps)) * unit;
}

}  // namespace

ApertureRange computeApertureRange(const LensSystem& lens, const FirstOrder& fo) {
    ApertureRange range;
    range.stopOnly = !conePasses(lens, fo, 1e-9, false) && conePasses(lens, fo, 1e-9, true);
    // Scan outward for the first blocked cone, then bisect; passing cones form [0, theta_max]
    // for real lenses, and the scan guards against an isolated passing band beyond a blocked one.
    constexpr int kScan = 256;
    double lo = 0, hi = 1.0;
    for (int k = 1; k <= kScan; ++k) {
        const double s = static_cast<double>(k) / kScan * 0.999999;
        if (!conePasses(lens, fo, s, range.stopOnly)) {
            hi = s;
            break;
        }
        lo = s;
    }
    if (lo == 0 && !conePasses(lens, fo, 1e-9, range.stopOnly))
        throw OpticsError("no ray from the rear focal point passes the lens: check the apertures");
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (conePasses(lens, fo, mid, range.stopOnly) ? lo : hi) = mid;
    }
    range.fstopMin = 1.0 / (2.0 * lo);
    // A lens slower than kNarrowestFstop at its widest (a micrometre stop, a kilometre focal length) still
    // has that one setting, rather than a range whose ends cross.
    range.fstopMax = std::max(narrowestPassingFstop(lens, fo, lo), range.fstopMin);
    range.fstopMaxOffered = range.fstopMax < kNarrowestFstop
                              ? std::max(atThreeDigits(0.98 * range.fstopMax, false), range.fstopMin)
                              : range.fstopMax;
    bool blocked = false;
    range.stopDiameterMax = 2.0 * stopHeight(lens, fo, lo, range.stopOnly, &blocked);
    return range;
}

double stopDiameterForFstop(const LensSystem& lens, const FirstOrder& fo, const ApertureRange& range,
                            double fstop) {
    // A relative tolerance lets the f-number printed for fstopMin be asked for again.
    if (!(fstop >= range.fstopMin * (1 - 1e-9)) || !(fstop <= range.fstopMax))
        throw OpticsError("f-number " + formatFNumber(fstop) + " is outside this lens's range " + fstopRangeText(range));
    const double sinTheta = std::min(1.0 / (2.0 * fstop), 1.0 / (2.0 * range.fstopMin));
    bool blocked = false;
    const double h = stopHeight(lens, fo, sinTheta, range.stopOnly, &blocked);
    if (blocked) throw OpticsError("f/" + formatFNumber(fstop) + ": the marginal ray is blocked behind the stop");
    return std::min(2.0 * h, 2.0 * lens.stop().apertureRadius);
}

double fstopForStopDiameter(const LensSystem& lens, const FirstOrder& fo, const ApertureRange& range, double diameter) {
    if (!(diameter > 0)) throw OpticsError("the stop diameter must be positive, got " + formatFNumber(diameter) + " mm");
    if (diameter >= range.stopDiameterMax) return range.fstopMin;
    // The opening shrinks as the cone narrows: bisect sin theta between the widest cone and none.
    double lo = 0, hi = 1.0 / (2.0 * range.fstopMin);
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        bool blocked = false;
        (2.0 * stopHeight(lens, fo, mid, range.stopOnly, &blocked) < diameter ? lo : hi) = mid;
    }
    return 1.0 / (2.0 * 0.5 * (lo + hi));
}

std::vector<double> fullStops(double fstopMin, double fstopMax) {
    std::vector<double> stops;
    for (int k = 0; k < 40; ++k) {
        // Exact powers of two, and those times sqrt 2: pow(sqrt 2, 12) is 64.00000000000006, past f/64.
        const double v = std::ldexp(k % 2 ? std::sqrt(2.0) : 1.0, k / 2);
        if (v > fstopMax) break;
        if (v >= fstopMin * (1 - 1e-9)) stops.push_back(v);
    }
    return stops;
}

std::string fstopRangeText(const ApertureRange& range) {
    double widest = atThreeDigits(range.fstopMin, true), narrowest = atThreeDigits(range.fstopMaxOffered, false);
    if (widest > narrowest) widest = narrowest = range.fstopMin;  // one setting (a lens slower than f/64)
    return "f/" + formatFNumber(widest) + " to f/" + formatFNumber(narrowest);
}

std::vector<double> fineStops(double fstopMin, double fstopMax, double step) {
    // A list to choose from, not a sweep: refuse a step or range that would never end.
    constexpr double kMaxCount = 1e5;
    const double first = std::ceil(fstopMin / step - 1e-9);
    if (!(step > 0) || !(std::fabs(first) < 1e15) || !((fstopMax + 1e-12) / step - first < kMaxCount))
        throw OpticsError("f-number steps of " + formatFNumber(step) + " from f/" + formatFNumber(fstopMin) + " to f/" +
                          formatFNumber(fstopMax) + " are not a finite list of at most 100000");
    std::vector<double> stops;
    for (long k = static_cast<long>(first); k * step <= fstopMax + 1e-12; ++k) stops.push_back(k * step);
    return stops;
}

}  // namespace lenslab
