#include "FilmErrorStudy.h"

#include <cmath>

#include "trace/ExactTrace.h"
#include "firstorder/ExitPupilBounds.h"

namespace lenslab::tradeoff {

namespace {

constexpr int kPupilGrid = 16;  // float rays per field position: a 16 x 16 grid over the pupil bounds

double landingX(const Ray& r, double z, double& y) {
    const double t = (z - r.origin.z) / r.direction.z;
    y = r.origin.y + t * r.direction.y;
    return r.origin.x + t * r.direction.x;
}

double floatError(const LensAnalysis& a, const ExitPupilBounds& bounds, const ComparisonPlane& plane, double r) {
    const Vec3 from{r, 0, a.focus.imageZExact};
    double worst = 0;
    for (int j = 0; j < kPupilGrid; ++j)
        for (int i = 0; i < kPupilGrid; ++i) {
            const PupilSample s = sampleExitPupil(bounds, r, 0, (i + 0.5) / kPupilGrid, (j + 0.5) / kPupilGrid);
            if (!(s.area > 0)) continue;
            const Ray ray{from, normalize(s.point - from)};
            const TraceResult d = traceRayT<double>(a.lens, ray, TraceDirection::FilmToScene);
            const TraceResult f = traceRayT<float>(a.lens, ray, TraceDirection::FilmToScene);
            if (!d.ok() || !f.ok()) continue;
            double yd, yf;
            const double xd = landingX(d.ray, plane.z, yd), xf = landingX(f.ray, plane.z, yf);
            worst = std::max(worst, std::hypot(xd - xf, yd - yf) / std::fabs(plane.magnification));
        }
    return worst;
}

}  // namespace

std::vector<FieldError> measureFieldErrors(const LensAnalysis& a) {
    const std::vector<FieldCase> fields = fieldCases();
    ThickLensFilmErrorOptions options;
    options.filmRadii = int(fields.size());
    const std::vector<ThickLensFilmError> thick = measureThickLensFilmError(a, 0, filmHalfDiagonalMm(), options);
    const ExitPupilBounds bounds = computeExitPupilBounds(a.lens, a.focus.imageZExact, filmHalfDiagonalMm());
    const ComparisonPlane plane = comparisonPlane(a);
    std::vector<FieldError> out;
    for (std::size_t i = 0; i < fields.size(); ++i)
        out.push_back({thick[i], floatError(a, bounds, plane, fields[i].fraction * filmHalfDiagonalMm())});
    return out;
}

}  // namespace lenslab::tradeoff
