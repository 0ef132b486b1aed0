#include "analysis/WavefrontMap.h"

#include <cmath>
#include <stdexcept>

#include "trace/ExactTrace.h"

namespace lenslab {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// Optical paths of the field's rays from a common wavefront in object space (the object point, or
// for a distant object the plane through the origin across the incoming light) to the sphere. Rays
// are asked for in scan order, each aimed from the last one's solution (a neighbour's).
class OpticalPaths {
public:
    OpticalPaths(const LensSystem& lens, const FieldAim& aim, Vec3 centre, double radius)
        : lens_(lens), aim_(aim), centre_(centre), radius_(radius) {}

    // The path of the ray through pupil point (px, py), with the ray leaving the lens; nullopt when blocked.
    std::optional<double> toSphere(double px, double py, bool ignoreApertures = false) {
        const std::optional<Ray> in = aimedRay(lens_, aim_, px, py, &guess_);
        if (!in) return std::nullopt;
        path_.clear();
        TraceOptions options;
        options.path = &path_;
        options.ignoreApertures = ignoreApertures;
        const TraceResult out = traceRay(lens_, *in, TraceDirection::SceneToFilm, options);
        if (!out.ok()) return std::nullopt;
        double opl = std::isinf(aim_.field.objectZ) ? dot(in->direction, in->origin) : 0.0;
        for (std::size_t k = 0; k + 1 < path_.size(); ++k)
            opl += lens_.indexBefore(static_cast<int>(k)) * length(path_[k + 1] - path_[k]);
        // On to the sphere: its nearer crossing, before the ray reaches the centre (may lie behind the
        // last surface when the exit pupil is inside the lens).
        const Vec3 oc = out.ray.origin - centre_;
        const double b = dot(out.ray.direction, oc), c = dot(oc, oc) - radius_ * radius_;
        const double disc = b * b - c;
        if (!(disc >= 0)) return std::nullopt;
        return opl + lens_.surfaces.back().indexAfter * (-b - std::sqrt(disc));
    }

private:
    const LensSystem& lens_;
    const FieldAim& aim_;
    Vec3 centre_;
    double radius_;
    std::vector<Vec3> path_;
    AimGuess guess_;
};

}  // namespace

std::optional<WavefrontMap> wavefrontMap(const LensSystem& lens, const FieldAim& aim, double imageZ, double exitPupilZ,
                                         const WavefrontOptions& options) {
    const int n = options.pupilSamples, sub = options.edgeSubsamples;
    if (n < 2 || n > 1024 || sub < 1 || sub > 16)
        throw std::invalid_argument("wavefront: 2 to 1024 pupil samples and 1 to 16 edge subsamples");
    WavefrontMap map;
    map.wavelength = lens.wavelength;
    map.samples = n;
    const std::optional<ImageSpaceAperture> aperture = imageSpaceAperture(lens, aim);
    if (!aperture || aperture->x == 0 || aperture->y == 0) return std::nullopt;
    map.aperture = *aperture;

    const std::optional<Ray> chiefIn = aimedRay(lens, aim, 0, 0);
    if (!chiefIn) return std::nullopt;
    TraceOptions unclipped;
    unclipped.ignoreApertures = true;
    const TraceResult chief = traceRay(lens, *chiefIn, TraceDirection::SceneToFilm, unclipped);
    if (!chief.ok()) return std::nullopt;
    const std::optional<Vec3> centre = pointOnPlane(chief.ray, imageZ), pupil = pointOnPlane(chief.ray, exitPupilZ);
    if (!centre || !pupil) return std::nullopt;
    map.chiefImage = {centre->x, centre->y};
    OpticalPaths paths(lens, aim, *centre, length(*centre - *pupil));
    const std::optional<double> chiefPath = paths.toSphere(0, 0, true);
    if (!chiefPath) return std::nullopt;

    const double lambda = lens.wavelength * 1e-6;  // mm
    auto phasor = [&](double opl) { return std::polar(1.0, kTwoPi * (opl - *chiefPath) / lambda); };
    // Cell (i, j) covers pupil coordinates whose direction cosines rise with i and j.
    const double signX = aperture->x > 0 ? 1 : -1, signY = aperture->y > 0 ? 1 : -1;
    auto pupilX = [&](double i) { return signX * (-1 + 2 * (i + 0.5) / n); };
    auto pupilY = [&](double j) { return signY * (-1 + 2 * (j + 0.5) / n); };

    std::vector<char> passes(static_cast<std::size_t>(n) * n, 0);
    map.pupilFunction.assign(passes.size(), Complex(0, 0));
    double sum = 0, sumSquares = 0;
    int passing = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double px = pupilX(i), py = pupilY(j);
            if (px * px + py * py > 1) continue;  // beyond the stop's rim
            if (const std::optional<double> opl = paths.toSphere(px, py)) {
                const std::size_t k = static_cast<std::size_t>(j) * n + i;
                passes[k] = 1;
                map.passingCells += 1;
                map.pupilFunction[k] = phasor(*opl);
                const double w = (*opl - *chiefPath) / lambda;
                sum += w, sumSquares += w * w, ++passing;
            }
        }
    if (passing > 0) map.rmsWaves = std::sqrt(std::max(0.0, sumSquares / passing - (sum / passing) * (sum / passing)));

    // Cells whose centre's passing differs from a neighbour's hold an edge: average the pupil
    // function over sub x sub rays there instead.
    auto passesAt = [&](int i, int j) { return i >= 0 && j >= 0 && i < n && j < n && passes[static_cast<std::size_t>(j) * n + i]; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool self = passesAt(i, j);
            if (self == passesAt(i - 1, j) && self == passesAt(i + 1, j) && self == passesAt(i, j - 1) &&
                self == passesAt(i, j + 1))
                continue;
            Complex mean = 0;
            int passed = 0;
            for (int b = 0; b < sub; ++b)
                for (int a = 0; a < sub; ++a) {
                    const double px = pupilX(i - 0.5 + (a + 0.5) / sub), py = pupilY(j - 0.5 + (b + 0.5) / sub);
                    if (px * px + py * py > 1) continue;
                    if (const std::optional<double> opl = paths.toSphere(px, py)) mean += phasor(*opl), ++passed;
                }
            map.passingCells += double(passed) / (sub * sub) - (self ? 1 : 0);
            map.pupilFunction[static_cast<std::size_t>(j) * n + i] = mean / double(sub * sub);
        }
    return map;
}

}  // namespace lenslab
