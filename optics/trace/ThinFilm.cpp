#include "trace/ThinFilm.h"

#include <cmath>
#include <complex>

namespace lenslab {

namespace {

using Complex = std::complex<double>;

// The cosine of the angle in a medium of index n for the invariant beta = n1 sin(theta1) (Snell).
// Past the critical angle it is imaginary, with the sign of a wave that decays into the medium
// (Macleod's convention, index n - ik).
Complex cosineIn(double n, double beta) {
    const double s = beta / n, c2 = 1 - s * s;
    return c2 >= 0 ? Complex(std::sqrt(c2), 0) : Complex(0, -std::sqrt(-c2));
}

// Tilted optical admittance (in units of free space's): n cos for s, n / cos for p.
Complex admittance(double n, Complex cosine, bool p) {
    constexpr double kTiny = 1e-12;  // exactly at the critical angle the p admittance is infinite
    if (std::abs(cosine) < kTiny) cosine = kTiny;
    return p ? n / cosine : n * cosine;
}

double reflectanceFor(double n1, double n2, const std::vector<CoatingLayer>& layers, bool reversed, double beta,
                      Complex cos1, double wavelengthNm, bool p, double& transmittance) {
    // [B C] = product of the layers' characteristic matrices times [1 eta_substrate].
    const Complex eta0 = admittance(n1, cos1, p), etaS = admittance(n2, cosineIn(n2, beta), p);
    Complex m11 = 1, m12 = 0, m21 = 0, m22 = 1;
    const int count = int(layers.size());
    for (int k = 0; k < count; ++k) {
        const CoatingLayer& l = layers[reversed ? count - 1 - k : k];
        const Complex cosL = cosineIn(l.index, beta);
        const Complex eta = admittance(l.index, cosL, p);
        const Complex delta = 2 * M_PI * l.index * l.thicknessNm * cosL / wavelengthNm;
        const Complex c = std::cos(delta), s = std::sin(delta), i(0, 1);
        const Complex a11 = m11 * c + m12 * i * eta * s, a12 = m11 * i * s / eta + m12 * c;
        const Complex a21 = m21 * c + m22 * i * eta * s, a22 = m21 * i * s / eta + m22 * c;
        m11 = a11, m12 = a12, m21 = a21, m22 = a22;
    }
    const Complex B = m11 + m12 * etaS, C = m21 + m22 * etaS;
    const Complex denominator = eta0 * B + C;
    const double R = std::norm((eta0 * B - C) / denominator);
    transmittance = 4 * eta0.real() * etaS.real() / std::norm(denominator);
    if (!std::isfinite(R) || !std::isfinite(transmittance)) {  // a film so thick its evanescent wave overflows
        transmittance = 0;
        return 1;
    }
    return R;
}

}  // namespace

InterfaceResponse thinFilmResponse(double n1, double n2, const std::vector<CoatingLayer>& layers, bool layersReversed,
                                   double cos1, double wavelengthNm) {
    cos1 = std::min(1.0, std::max(0.0, cos1));
    if (cos1 == 0) return {1, 0};  // grazing: every polarisation is reflected
    const double beta = n1 * std::sqrt(1 - cos1 * cos1);
    InterfaceResponse r;
    double ts, tp;
    const double rs = reflectanceFor(n1, n2, layers, layersReversed, beta, cos1, wavelengthNm, false, ts);
    const double rp = reflectanceFor(n1, n2, layers, layersReversed, beta, cos1, wavelengthNm, true, tp);
    r.reflectance = 0.5 * (rs + rp);
    r.transmittance = 0.5 * (ts + tp);
    return r;
}

InterfaceResponse surfaceResponse(const LensSystem& lens, int i, bool fromScene, double cos1, double wavelengthNm) {
    const Surface& s = lens.surfaces[i];
    if (s.mirror) return {1, 0};
    const Medium& before = i == 0 ? air() : lens.surfaces[i - 1].mediumAfter;
    const double nScene = refractiveIndex(before, wavelengthNm), nFilm = refractiveIndex(s.mediumAfter, wavelengthNm);
    // The coating's outer side is its air side; between two glasses (or two airs), the scene side.
    const bool outerIsScene = !(lens.indexBefore(i) != 1.0 && s.indexAfter == 1.0);
    return fromScene ? thinFilmResponse(nScene, nFilm, s.coating.layers, !outerIsScene, cos1, wavelengthNm)
                     : thinFilmResponse(nFilm, nScene, s.coating.layers, outerIsScene, cos1, wavelengthNm);
}

}  // namespace lenslab
