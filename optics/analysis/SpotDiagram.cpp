#include "analysis/SpotDiagram.h"

#include <algorithm>
#include <cmath>

#include "trace/ExactTrace.h"

namespace lenslab {

SpotDiagram spotDiagram(const LensSystem& lens, const FieldAim& aim, double imageZ, Point2 reference,
                        const std::vector<Point2>& pupil) {
    SpotDiagram spot;
    spot.wavelength = lens.wavelength;
    spot.raysLaunched = static_cast<int>(pupil.size());
    for (const Point2& p : pupil) {
        const std::optional<Ray> in = aimedRay(lens, aim, p.x, p.y);
        if (!in) continue;
        const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm);
        if (!out.ok()) continue;
        if (const std::optional<Vec3> hit = pointOnPlane(out.ray, imageZ))
            spot.points.push_back({hit->x - reference.x, hit->y - reference.y});
    }
    if (spot.points.empty()) return spot;
    for (const Point2& q : spot.points) spot.centroid.x += q.x, spot.centroid.y += q.y;
    spot.centroid.x /= spot.points.size();
    spot.centroid.y /= spot.points.size();
    double sum = 0;
    for (const Point2& q : spot.points) {
        const double r2 = (q.x - spot.centroid.x) * (q.x - spot.centroid.x) + (q.y - spot.centroid.y) * (q.y - spot.centroid.y);
        sum += r2;
        spot.geometricRadius = std::max(spot.geometricRadius, std::sqrt(r2));
    }
    spot.rmsRadius = std::sqrt(sum / spot.points.size());
    return spot;
}

}  // namespace lenslab
