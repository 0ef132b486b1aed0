#include "analysis/SpotDiagram.h"

#include <algorithm>
#include <cmath>

#include "trace/ExactTrace.h"

namespace lenslab {

double ImageRays::arrivingWeight() const {
    double sum = 0;
    for (double w : weight) sum += w;
    return sum;
}

Point2 ImageRays::pointOn(std::size_t i, double planeZ) const {
    const double dz = planeZ - z;
    return {at[i].x + slope[i].x * dz, at[i].y + slope[i].y * dz};
}

namespace {

// Rays of the field along one line across the stop: from `centre` (normalised stop coordinates)
// along `step`, the point centre + t step labelled by u = t^2, out to the stop's rim at uRim. Each
// aim starts from the last solved one on the line (continuation).
struct RadialRay {
    const LensSystem& lens;
    const FieldAim& aim;
    Point2 centre, step;
    double uRim = 1;
    mutable AimGuess guess;

    std::optional<Ray> passing(double u) const {
        const double t = std::sqrt(std::clamp(u, 0.0, uRim));
        const std::optional<Ray> in = aimedRay(lens, aim, centre.x + t * step.x, centre.y + t * step.y, &guess);
        if (!in) return std::nullopt;
        const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm);
        if (!out.ok() || out.ray.direction.z == 0) return std::nullopt;
        return out.ray;
    }
};

// Where along u in [lo, hi] passing turns to blocked or back (one end passes, the other not).
double rim(const RadialRay& radial, double lo, double hi, bool loPasses) {
    const double precision = 1e-5 * radial.uRim;  // far below what moves an RMS radius by 1e-4
    while (hi - lo > precision) {
        const double mid = 0.5 * (lo + hi);
        (radial.passing(mid).has_value() == loPasses ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The stretches [u0, u1] of a line whose rays pass: a scan, then each change of state bisected.
// Where the passing part of the stop is convex (no obscuration cuts a hole in it) and the line starts
// inside it, it is one stretch from the start: only its far end needs finding.
std::vector<std::pair<double, double>> passingStretches(const RadialRay& radial, int scan, bool convex) {
    if (convex && radial.passing(0)) {
        if (radial.passing(radial.uRim)) return {{0, radial.uRim}};
        return {{0, rim(radial, 0, radial.uRim, true)}};
    }
    std::vector<std::pair<double, double>> stretches;
    bool previous = radial.passing(0).has_value();
    double start = 0, previousU = 0;
    for (int k = 1; k <= scan; ++k) {
        const double u = radial.uRim * k / scan;
        const bool passes = radial.passing(u).has_value();
        if (passes != previous) {
            const double edge = rim(radial, previousU, u, previous);
            if (previous) stretches.push_back({start, edge});
            else start = edge;
        }
        previous = passes;
        previousU = u;
    }
    if (previous) stretches.push_back({start, radial.uRim});
    return stretches;
}

// The polar quadrature's frame over the passing part of the stop: p = centre + M q, q polar. The
// centre is the centroid of the passing points of a grid over the stop, and M twice the Cholesky
// factor of their covariance, so that the passing region maps to about the unit disk (the whole
// stop is mapped to itself). Polar lines from inside a vignetted pupil meet each rim once, and a
// region that is round in q has no narrow tips for equally spaced azimuths to miss: the rims move
// smoothly with the azimuth and the quadrature converges quickly. From a point on a rim (the stop's
// centre at a field whose chief ray just passes) the lines' lengths would jump instead.
struct PolarFrame {
    Point2 centre;
    double m[2][2] = {{1, 0}, {0, 1}};  // lower triangular
    double determinant() const { return m[0][0] * m[1][1]; }
    Point2 apply(Point2 q) const { return {m[0][0] * q.x, m[1][0] * q.x + m[1][1] * q.y}; }
};

PolarFrame passingFrame(const LensSystem& lens, const FieldAim& aim) {
    constexpr int kGrid = 11;
    std::vector<Point2> passing;
    int total = 0;
    AimGuess guess;  // each grid point aimed from the last one's solution
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            const Point2 p{-1 + 2.0 * (i + 0.5) / kGrid, -1 + 2.0 * (j + 0.5) / kGrid};
            if (p.x * p.x + p.y * p.y > 1) continue;
            ++total;
            const std::optional<Ray> in = aimedRay(lens, aim, p.x, p.y, &guess);
            if (in && traceRay(lens, *in, TraceDirection::SceneToFilm).ok()) passing.push_back(p);
        }
    PolarFrame frame;
    if (passing.size() < 3 || int(passing.size()) == total) return frame;
    for (const Point2& p : passing) frame.centre.x += p.x, frame.centre.y += p.y;
    frame.centre.x /= passing.size(), frame.centre.y /= passing.size();
    double xx = 0, xy = 0, yy = 0;
    for (const Point2& p : passing) {
        const double dx = p.x - frame.centre.x, dy = p.y - frame.centre.y;
        xx += dx * dx, xy += dx * dy, yy += dy * dy;
    }
    // The grid's own spacing keeps a one-row region from collapsing to a line.
    const double cell = 4.0 / (kGrid * kGrid * 12);
    xx = xx / passing.size() + cell, xy /= passing.size(), yy = yy / passing.size() + cell;
    const double l00 = std::sqrt(xx), l10 = xy / l00, l11 = std::sqrt(std::max(yy - l10 * l10, cell));
    frame.m[0][0] = 2 * l00, frame.m[1][0] = 2 * l10, frame.m[1][1] = 2 * l11;
    return frame;
}

// The rays of one line of the frame's polar quadrature: the stretches whose rays pass (scanned, their
// ends bisected to the rims), then the quadrature's nodes on each; a node that does not pass after
// all is left out. Weights are per line (a quadrature of A lines divides them by A).
struct LineRays {
    std::vector<Point2> at, slope;
    std::vector<double> weight;
    int launched = 0;
    bool whole = false;  // one stretch from the centre to the stop's rim, every node passing
};

LineRays traceLine(const LensSystem& lens, const FieldAim& aim, double z, const PolarFrame& frame,
                   const std::vector<std::pair<double, double>>& nodes, Point2 direction, bool convex) {
    LineRays line;
    const Point2 c = frame.centre, v = frame.apply(direction);
    // The line's length to the stop's rim: |c + t v| = 1.
    const double a = v.x * v.x + v.y * v.y, b = c.x * v.x + c.y * v.y, cc = c.x * c.x + c.y * c.y;
    const double t = (-b + std::sqrt(std::max(0.0, b * b - a * (cc - 1)))) / a;
    const RadialRay radial{lens, aim, c, v, t * t, {}};
    // The scan finds stretches as narrow as 1 / scan of the line's length squared.
    const int scan = std::max(16, 2 * int(nodes.size()));
    const std::vector<std::pair<double, double>> stretches = passingStretches(radial, scan, convex);
    line.whole = stretches.size() == 1 && stretches[0].first == 0 && stretches[0].second == radial.uRim;
    for (const auto& [u0, u1] : stretches)
        for (const auto& [x, w] : nodes) {
            ++line.launched;
            const std::optional<Ray> out = radial.passing(u0 + (u1 - u0) * x);
            const std::optional<Vec3> hit = out ? pointOnPlane(*out, z) : std::nullopt;
            line.whole = line.whole && hit;
            if (!hit) continue;
            line.at.push_back({hit->x, hit->y});
            line.slope.push_back({out->direction.x / out->direction.z, out->direction.y / out->direction.z});
            // The stop's area element |det M| t dt dphi = |det M| du dphi / 2, over the stop's pi.
            line.weight.push_back(frame.determinant() * w * (u1 - u0));
        }
    return line;
}

// A quadrature's rays from its lines (lines[k] on azimuth k of lines.size()).
ImageRays assemble(const std::vector<LineRays>& lines, double wavelength, double z, PupilQuadrature quadrature) {
    ImageRays rays;
    rays.wavelength = wavelength;
    rays.z = z;
    rays.sampling = quadrature;
    for (const LineRays& line : lines) {
        rays.at.insert(rays.at.end(), line.at.begin(), line.at.end());
        rays.slope.insert(rays.slope.end(), line.slope.begin(), line.slope.end());
        for (double w : line.weight) rays.weight.push_back(w / quadrature.azimuths);
        rays.launched += line.launched;
    }
    return rays;
}

double rmsAboutCentroid(const ImageRays& rays) {
    return spotStatistics(rays.at, rays.weight).rmsRadius;
}

}  // namespace

ImageRays settledImageRays(const LensSystem& lens, const FieldAim& aim, double z, PupilQuadrature start,
                           double tolerance, int maxAzimuths) {
    // Where no aperture but the stop's can clip (the others automatic, nothing obscured), the passing
    // part of the stop is the whole stop unless rays fail on their own (total internal reflection, a
    // surface missed), and the grid's frame is the stop itself: the lines are traced in it first, and
    // the grid is searched only if some line does not pass whole.
    const bool onlyTheStopClips = std::all_of(lens.surfaces.begin(), lens.surfaces.end(), [](const Surface& s) {
        return (s.isStop || s.automaticAperture) && s.obscurationRadius == 0 && !s.clearShape && !s.obscurationShape;
    });
    bool assumedWhole = onlyTheStopClips;
    const auto nodes = gaussLegendreUnit(start.rings);
    for (;;) {
        const PolarFrame frame = assumedWhole ? PolarFrame{} : passingFrame(lens, aim);
        // Clear apertures are round: what passes them all is convex unless an obscuration cuts a hole.
        const bool convex = std::none_of(lens.surfaces.begin(), lens.surfaces.end(), [](const Surface& s) { return s.obscurationRadius > 0; });
        bool broken = false;  // a line that does not pass whole, where the frame was assumed
        const auto line = [&](int k, int of) {
            LineRays l = traceLine(lens, aim, z, frame, nodes, azimuthDirection(k, of), convex);
            broken = broken || (assumedWhole && !l.whole);
            return l;
        };
        std::vector<LineRays> lines;
        for (int k = 0; k < start.azimuths; ++k) lines.push_back(line(k, start.azimuths));
        ImageRays rays = assemble(lines, lens.wavelength, z, start);
        // Each doubling keeps the lines it has (azimuth k of A is azimuth 2k of 2A) and adds those between.
        while (!broken && rays.sampling.doubled().azimuths <= maxAzimuths) {
            const PupilQuadrature finer = rays.sampling.doubled();
            std::vector<LineRays> next;
            for (int k = 0; k < finer.azimuths; ++k) next.push_back(k % 2 == 0 ? std::move(lines[k / 2]) : line(k, finer.azimuths));
            lines = std::move(next);
            ImageRays fine = assemble(lines, lens.wavelength, z, finer);
            const double before = rmsAboutCentroid(rays), after = rmsAboutCentroid(fine);
            // Both spots empty, or both points: nothing left to settle.
            fine.samplingChange = after > 0 ? std::fabs(before / after - 1) : (before > 0 ? 1.0 : 0.0);
            rays = std::move(fine);
            if (rays.samplingChange <= tolerance) break;
        }
        if (!broken) return rays;
        assumedWhole = false;
    }
}

SpotStatistics spotStatistics(const std::vector<Point2>& points, const std::vector<double>& weights,
                              std::optional<Point2> about) {
    SpotStatistics s;
    double total = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        s.centroid.x += weights[i] * points[i].x;
        s.centroid.y += weights[i] * points[i].y;
        total += weights[i];
    }
    if (!(total > 0)) return s;
    s.centroid.x /= total;
    s.centroid.y /= total;
    const Point2 c = about.value_or(s.centroid);
    double sum = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double r2 = (points[i].x - c.x) * (points[i].x - c.x) + (points[i].y - c.y) * (points[i].y - c.y);
        sum += weights[i] * r2;
        s.geometricRadius = std::max(s.geometricRadius, std::sqrt(r2));
    }
    s.rmsRadius = std::sqrt(sum / total);
    return s;
}

SpotDiagram spotDiagram(const ImageRays& rays, double imageZ, Point2 origin, std::optional<Point2> about) {
    SpotDiagram spot;
    spot.wavelength = rays.wavelength;
    spot.raysLaunched = rays.launched;
    spot.sampling = rays.sampling;
    spot.samplingChange = rays.samplingChange;
    spot.weights = rays.weight;
    spot.points.reserve(rays.at.size());
    for (std::size_t i = 0; i < rays.at.size(); ++i) {
        const Point2 p = rays.pointOn(i, imageZ);
        spot.points.push_back({p.x - origin.x, p.y - origin.y});
    }
    spot.statistics = spotStatistics(spot.points, spot.weights, about);
    spot.transmission = rays.arrivingWeight();
    return spot;
}

}  // namespace lenslab
