#include "firstorder/Aperture.h"

#include "prescription/NumberText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

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

// How far from the stop's centre, in its plane, the marginal ray traced from F' through the surfaces
// behind the stop crosses it (in the stop's own frame: a decentred stop's centre is off the axis
// of the coordinates arriving at it).
double stopHeight(const LensSystem& lens, const FirstOrder& fo, double sinTheta, bool stopOnly, bool* blocked) {
    TraceOptions options;
    options.begin = lens.stopIndex + 1;
    options.ignoreObscurations = true;
    options.stopApertureOnly = stopOnly;
    const TraceResult r = traceRay(lens, marginalRayFromFPrime(fo, sinTheta), TraceDirection::FilmToScene, options);
    *blocked = !r.ok();
    if (lens.stop().after.isIdentity()) return std::fabs(heightAtZ(r.ray, lens.stop().z));
    const Ray inStop = movedRay(motionInto(lens.stop(), TraceDirection::FilmToScene), r.ray);
    const double t = (lens.stop().z - inStop.origin.z) / inStop.direction.z;
    return std::hypot(inStop.origin.x + t * inStop.direction.x, inStop.origin.y + t * inStop.direction.y);
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
    bool blocked = false;
    range.stopDiameterMax = 2.0 * stopHeight(lens, fo, lo, range.stopOnly, &blocked);
    return range;
}

double stopDiameterForFstop(const LensSystem& lens, const FirstOrder& fo, const ApertureRange& range,
                            double fstop) {
    // A relative tolerance lets the f-number printed for fstopMin be asked for again.
    if (!(fstop >= range.fstopMin * (1 - 1e-9)) || !(fstop <= range.fstopMax))
        throw OpticsError("f-number " + formatFNumber(fstop) + " is outside this lens's range f/" +
                          formatFNumber(range.fstopMin) + " to f/" + formatFNumber(range.fstopMax));
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
        const double v = std::pow(std::sqrt(2.0), k);
        if (v > fstopMax * (1 + 1e-12)) break;
        if (v >= fstopMin * (1 - 1e-9)) stops.push_back(v);
    }
    return stops;
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
