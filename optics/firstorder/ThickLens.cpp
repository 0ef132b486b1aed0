#include "firstorder/ThickLens.h"

#include <cmath>

#include "trace/NearAxis.h"

namespace lenslab {

ThickLens makeThickLens(const FirstOrder& fo, const Pupils& pupils) {
    return {fo.efl, fo.zP, fo.zPPrime, pupils.entrance, pupils.exit};
}

namespace {

Matrix4 translateZ(double dz) {
    return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, dz}, {0, 0, 0, 1}}};
}

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 m{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) m[i][j] += a[i][k] * b[k][j];
    return m;
}

Matrix4 projective(double wPerZ) {
    return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, wPerZ, 1}}};
}

}  // namespace

Matrix4 objectToImageMatrix(const ThickLens& lens) {
    return multiply(translateZ(lens.zPPrime), multiply(projective(-1.0 / lens.f), translateZ(-lens.zP)));
}

Matrix4 imageToObjectMatrix(const ThickLens& lens) {
    return multiply(translateZ(lens.zP), multiply(projective(1.0 / lens.f), translateZ(-lens.zPPrime)));
}

TraceResult traceThick(const ThickLens& lens, const Ray& ray, TraceDirection direction) {
    const bool toFilm = direction == TraceDirection::SceneToFilm;
    const double zIn = toFilm ? lens.zP : lens.zPPrime;
    const double zOut = toFilm ? lens.zPPrime : lens.zP;
    const Pupil& pupil = toFilm ? lens.entrance : lens.exit;
    const Vec3 d = ray.direction;
    TraceResult result;
    result.ray = ray;
    const double outward = toFilm ? -1.0 : 1.0;
    if (!(d.z * outward > 0)) {
        result.blocked = BlockReason::MissedSurface;
        return result;
    }
    // The pupil stands in for the stop.
    const double tp = (pupil.z - ray.origin.z) / d.z;
    const double px = ray.origin.x + tp * d.x, py = ray.origin.y + tp * d.y;
    if (px * px + py * py > 0.25 * pupil.diameter * pupil.diameter) {
        result.blocked = BlockReason::ClippedByStop;
        return result;
    }
    const double t = (zIn - ray.origin.z) / d.z;
    const double qx = ray.origin.x + t * d.x, qy = ray.origin.y + t * d.y;
    // The conjugate of a point on the incoming ray (a focal length before the principal plane) lies
    // on the outgoing ray. Keeping it homogeneous (h.w not divided out) keeps points at infinity
    // (w = 0, on a focal plane) exact: the outgoing direction is -(h.xyz - h.w * q_out).
    const Matrix4 m = toFilm ? objectToImageMatrix(lens) : imageToObjectMatrix(lens);
    const double p[4] = {qx - lens.f * d.x, qy - lens.f * d.y, zIn - lens.f * d.z, 1.0};
    double h[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) h[i] += m[i][k] * p[k];
    const Vec3 dir{h[3] * qx - h[0], h[3] * qy - h[1], h[3] * zOut - h[2]};
    const double len = length(dir);
    if (!(len > 0) || !(dir.z * outward > 0)) {
        result.blocked = BlockReason::MissedSurface;
        return result;
    }
    result.ray = {{qx, qy, zOut}, (1.0 / len) * dir};
    return result;
}

std::vector<ThickLensErrorSample> thickLensError(const LensSystem& lens, const ThickLens& thick,
                                                 const FirstOrder& fo, const std::vector<double>& heights) {
    std::vector<ThickLensErrorSample> samples;
    const double zIn = lens.frontZ() + lens.surfaces.front().apertureRadius + 1.0;
    ThickLens unclipped = thick;
    unclipped.entrance.diameter = 1e300;  // compare geometry only; the exact trace reports clipping
    for (double h : heights) {
        ThickLensErrorSample s;
        s.height = h;
        const Ray in{{0, h, zIn}, {0, 0, -1}};
        const TraceResult exact = traceRay(lens, in, TraceDirection::SceneToFilm);
        const TraceResult approx = traceThick(unclipped, in, TraceDirection::SceneToFilm);
        if (!exact.ok() || !approx.ok() || exact.ray.direction.y == 0) {
            s.blocked = true;
        } else {
            s.transverseError = heightAtZ(exact.ray, fo.zFPrime) - heightAtZ(approx.ray, fo.zFPrime);
            s.angleError = std::atan2(exact.ray.direction.y, -exact.ray.direction.z) -
                           std::atan2(approx.ray.direction.y, -approx.ray.direction.z);
        }
        samples.push_back(s);
    }
    return samples;
}

}  // namespace lenslab
