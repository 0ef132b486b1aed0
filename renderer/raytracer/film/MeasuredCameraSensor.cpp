#include "film/MeasuredCameraSensor.h"

#include <stdexcept>

#include "core/ColourCheckerSwatches.h"
#include "core/ColourMatching.h"
#include "core/DaylightSpectrum.h"
#include "core/Spectrum.h"

namespace lenslab {

namespace {

constexpr int kCurveFirstNm = 360, kCurveLastNm = 830;

// The Smits coefficients of the colour is found by fixed-point steps: a spectrum's CIE colour is
// within a few percent of its coefficients' (3% in blue for a sky blue), so each step shrinks the
// error some thirtyfold.
constexpr int kInversionSteps = 5;

// The CIE 1931 tristimulus values of a spectrum, summed as sensorRgb sums.
Triple cieXyz(const std::function<double(double)>& spectrum) {
    Triple xyz{0, 0, 0};
    for (int nm = kCurveFirstNm; nm <= kCurveLastNm; ++nm) {
        const double s = spectrum(nm);
        xyz[0] += cieX(nm) * s;
        xyz[1] += cieY(nm) * s;
        xyz[2] += cieZ(nm) * s;
    }
    return xyz;
}

double d65(double nm) { return daylightSpectrum(6504, nm); }

Vec3f combine(const std::array<Vec3f, kSmitsBases>& perBasis, const std::array<float, kSmitsBases>& c) {
    Vec3f sum{0, 0, 0};
    for (int k = 0; k < kSmitsBases; ++k) sum += c[k] * perBasis[k];
    return sum;
}


}  // namespace

MeasuredCameraSensor::MeasuredCameraSensor(const CameraSensorCurves& curves, double whiteBalanceKelvin)
    : curves_(curves), illuminantCct_(whiteBalanceKelvin * 1.4388 / 1.4380) {
    // pbrt-v4's fit: each swatch's sensor RGB and target XYZ, both relative to the illuminant's
    // green (sensor) response, the target at the illuminant's luminance; least squares by the
    // normal equations, A^T A M^T = A^T B.
    const double illuminantG = sensorRgb([&](double nm) { return illuminant(nm); })[1];
    const double illuminantY = cieXyz([&](double nm) { return illuminant(nm); })[1];
    const double d65Y = cieXyz(d65)[1];
    Matrix3 ata{}, atb{};
    for (int i = 0; i < kColourCheckerSwatches; ++i) {
        const TabulatedSpectrum swatch = colourCheckerSwatch(i);
        Triple a = sensorRgb([&](double nm) { return swatch(nm) * illuminant(nm); });
        Triple b = cieXyz([&](double nm) { return swatch(nm) * d65(nm); });
        for (int c = 0; c < 3; ++c) {
            a[c] /= illuminantG;
            b[c] *= illuminantY / (d65Y * illuminantG);
        }
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                ata[r * 3 + c] += a[r] * a[c];
                atb[r * 3 + c] += a[r] * b[c];
            }
    }
    const std::optional<Matrix3> ataInverse = inverse(ata);
    if (!ataInverse) throw std::logic_error(std::string("camera sensor ") + curves.name + ": singular colour fit");
    xyzFromSensorRgb_ = transpose(multiply(*ataInverse, atb));

    for (int k = 0; k < kSmitsBases; ++k) {
        const auto light = [&](double nm) { return smitsBasis(SmitsBasis(k), nm) * d65(nm) / d65Y; };
        const Triple xyz = cieXyz(light), film = applyMatrix(xyzFromSensorRgb_, sensorRgb(light));
        cieOfBasis_[k] = xyzToRgb(xyz[0], xyz[1], xyz[2]);
        filmOfBasis_[k] = xyzToRgb(film[0], film[1], film[2]);
    }
}

Triple MeasuredCameraSensor::sensorRgb(const std::function<double(double)>& spectrum) const {
    Triple rgb{0, 0, 0};
    for (int nm = kCurveFirstNm; nm <= kCurveLastNm; ++nm) {
        const double s = spectrum(nm);
        rgb[0] += curves_.r(nm) * s;
        rgb[1] += curves_.g(nm) * s;
        rgb[2] += curves_.b(nm) * s;
    }
    return rgb;
}

double MeasuredCameraSensor::illuminant(double nm) const {
    return illuminantCct_ < 4000 ? planckRadiance(illuminantCct_, nm) : daylightSpectrum(illuminantCct_, nm);
}

Vec3f MeasuredCameraSensor::toFilm(const Vec3f& rgb) const {
    Vec3f w = rgb;
    for (int step = 0; step < kInversionSteps; ++step) w += rgb - combine(cieOfBasis_, smitsCoefficients(w));
    return combine(filmOfBasis_, smitsCoefficients(w));
}

}  // namespace lenslab
