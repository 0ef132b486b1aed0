#include "firstorder/ChiefRay.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "trace/ExactTrace.h"
#include "trace/NearAxis.h"
#include "prescription/OpticsError.h"
#include "prescription/Pi.h"

namespace lenslab {

namespace {

// Rays of one field angle, labelled by the height at which they cross the front vertex plane.
struct FieldRays {
    const LensSystem& lens;
    double sinT, cosT;
    double zIn;  // start plane, in front of every surface cap

    Ray at(double vertexHeight) const {
        const double t = (zIn - lens.frontZ()) / cosT;
        return {{0, vertexHeight + t * sinT, zIn}, {0, -sinT, -cosT}};
    }

    // Height at the stop plane after the elements in front of it, in the stop's own frame (a
    // decentred stop's centre is off the axis of the coordinates arriving at it); nullopt when the
    // ray cannot get there.
    std::optional<double> stopHeight(double vertexHeight) const {
        TraceOptions options;
        options.end = lens.stopIndex;
        options.ignoreApertures = true;
        const TraceResult r = traceRay(lens, at(vertexHeight), TraceDirection::SceneToFilm, options);
        if (!r.ok() || !(r.ray.direction.z * lens.zDirectionAfter(lens.stopIndex - 1) > 0)) return std::nullopt;
        const RigidMotion& intoStop = lens.stop().before;  // motionInto(stop, SceneToFilm)
        return heightAtZ(intoStop.isIdentity() ? r.ray : movedRay(intoStop, r.ray), lens.stop().z);
    }
};

}  // namespace

std::optional<Ray> chiefRay(const LensSystem& lens, double fieldDegrees) {
    if (!(std::fabs(fieldDegrees) < 90)) throw OpticsError("chief ray: the field angle must lie below 90 degrees");
    const double theta = fieldDegrees * kPi / 180;
    double reach = 0;
    for (const Surface& s : lens.surfaces) reach = std::max(reach, s.apertureRadius);
    const FieldRays rays{lens, std::sin(theta), std::cos(theta), lens.frontZ() + lens.surfaces.front().apertureRadius + 1.0};
    // Scan the vertex heights for a sign change of the stop height; take the bracket nearest the
    // axis (the entrance pupil lies near it), then bisect. The scan's cells are visited from the
    // axis outward (of two at the same distance, the one below it first), so the first bracket found
    // is that one: a lens whose pupil lies near its axis needs a few of the 400 traces, not all.
    constexpr int kScan = 400;
    const double span = 3 * reach;
    std::vector<std::optional<double>> heights(kScan + 1);
    std::vector<bool> traced(kScan + 1, false);
    const auto heightAt = [&](int k) -> const std::optional<double>& {
        if (!traced[k]) {
            heights[k] = rays.stopHeight(-span + 2 * span * k / kScan);
            traced[k] = true;
        }
        return heights[k];
    };
    std::vector<int> cells(kScan);  // cell k spans grid points k - 1 and k
    for (int k = 1; k <= kScan; ++k) cells[k - 1] = k;
    std::stable_sort(cells.begin(), cells.end(), [](int a, int b) { return std::abs(2 * a - 1 - kScan) < std::abs(2 * b - 1 - kScan); });
    std::optional<std::pair<double, double>> bracket;
    for (int k : cells) {
        const std::optional<double>& below = heightAt(k - 1);
        const std::optional<double>& above = heightAt(k);
        if (below && above && (*below <= 0) != (*above <= 0)) {
            bracket = {{-span + 2 * span * (k - 1) / kScan, -span + 2 * span * k / kScan}};
            break;
        }
    }
    if (!bracket) return std::nullopt;
    auto [lo, hi] = *bracket;
    const bool loNegative = *rays.stopHeight(lo) <= 0;
    for (int it = 0; it < 100 && hi - lo > 1e-13 * reach; ++it) {
        const double mid = 0.5 * (lo + hi);
        const std::optional<double> g = rays.stopHeight(mid);
        if (!g) return std::nullopt;
        ((*g <= 0) == loNegative ? lo : hi) = mid;
    }
    return rays.at(0.5 * (lo + hi));
}

}  // namespace lenslab
