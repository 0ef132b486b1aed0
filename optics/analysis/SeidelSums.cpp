#include "analysis/SeidelSums.h"

#include <cmath>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

// A paraxial ray in the designer's frame (light along +s = -z): its height and slope in front of
// each surface, and its slope after it.
struct ParaxialPath {
    std::vector<double> height, slopeBefore, slopeAfter;
};

ParaxialPath traceParaxial(const LensSystem& lens, double y, double u) {
    ParaxialPath p;
    const int n = static_cast<int>(lens.surfaces.size());
    for (int k = 0; k < n; ++k) {
        const Surface& s = lens.surfaces[k];
        const double before = lens.indexBefore(k), after = s.indexAfter;
        p.height.push_back(y);
        p.slopeBefore.push_back(u);
        u = (before * u - y * (after - before) * s.vertexCurvature()) / after;
        p.slopeAfter.push_back(u);
        if (k + 1 < n) y += (s.z - lens.surfaces[k + 1].z) * u;
    }
    return p;
}

// a p + b q, surface by surface.
ParaxialPath combined(double a, const ParaxialPath& p, double b, const ParaxialPath& q) {
    ParaxialPath r = p;
    for (std::size_t k = 0; k < p.height.size(); ++k) {
        r.height[k] = a * p.height[k] + b * q.height[k];
        r.slopeBefore[k] = a * p.slopeBefore[k] + b * q.slopeBefore[k];
        r.slopeAfter[k] = a * p.slopeAfter[k] + b * q.slopeAfter[k];
    }
    return r;
}

double colourOf(const Medium& m) { return refractiveIndex(m, kWavelengthF) - refractiveIndex(m, kWavelengthC); }

}  // namespace

std::optional<SeidelSums> seidelSums(const LensSystem& lens, double fieldDegrees, double objectZ) {
    for (const Surface& s : lens.surfaces)
        if (s.isMoved() || s.mirror || !s.form.isEvenAsphere()) return std::nullopt;
    if (lens.decentred) return std::nullopt;
    const int stop = lens.stopIndex;
    // Two independent rays from the front vertex: A at height 1 parallel to the axis, B through the
    // vertex at slope 1. The marginal ray leaves the axial object point (A alone for a distant one)
    // and is scaled to the stop's rim; the chief ray has the field's slope and crosses the stop's centre.
    const ParaxialPath a = traceParaxial(lens, 1, 0), b = traceParaxial(lens, 0, 1);
    const double distance = objectZ - lens.frontZ();  // object in front of the front vertex
    ParaxialPath marginal = std::isfinite(distance) ? combined(distance, a, 1, b) : a;
    if (!(std::fabs(marginal.height[stop]) > 0) || !(std::fabs(a.height[stop]) > 0)) return std::nullopt;
    marginal = combined(lens.stop().apertureRadius / marginal.height[stop], marginal, 0, b);
    const double ubar = std::tan(fieldDegrees * kPi / 180);
    // ubar (alpha A + B) with alpha A + B crossing the stop at height 0.
    const ParaxialPath chief = combined(-ubar * b.height[stop] / a.height[stop], a, ubar, b);

    SeidelSums out;
    out.fieldDegrees = fieldDegrees;
    out.marginalHeight = lens.stop().apertureRadius;
    out.lagrangeInvariant = chief.slopeBefore[0] * marginal.height[0] - marginal.slopeBefore[0] * chief.height[0];
    const double h = out.lagrangeInvariant;
    for (std::size_t k = 0; k < lens.surfaces.size(); ++k) {
        const Surface& s = lens.surfaces[k];
        const double n0 = lens.indexBefore(int(k)), n1 = s.indexAfter;
        const double c = s.vertexCurvature();
        const double y = marginal.height[k], u0 = marginal.slopeBefore[k], u1 = marginal.slopeAfter[k];
        const double ybar = chief.height[k], ubar0 = chief.slopeBefore[k];
        const double refraction = n0 * (u0 + y * c), refractionBar = n0 * (ubar0 + ybar * c);  // A, Abar
        const double du = u1 / n1 - u0 / n0;
        SeidelTerms t;
        t.spherical = -refraction * refraction * y * du;
        t.coma = -refraction * refractionBar * y * du;
        t.astigmatism = -refractionBar * refractionBar * y * du;
        t.petzval = -h * h * c * (1 / n1 - 1 / n0);
        t.distortion = refraction != 0 ? refractionBar / refraction * (t.astigmatism + t.petzval) : 0.0;
        // The fourth-order sag beyond the vertex sphere's, (1 + k) c^3 / 8 + the r^4 term - cv^3 / 8,
        // is a thin plate at the surface: 8 a4 dn y^4 of spherical aberration, carried to the others
        // by ybar / y.
        const double a4 = (1 + s.conic) * std::pow(s.curvature, 3) / 8 + s.aspheric[1] - c * c * c / 8;
        if (a4 != 0 && y != 0) {
            const double plate = 8 * a4 * (n1 - n0) * std::pow(y, 4), q = ybar / y;
            t.spherical += plate;
            t.coma += plate * q;
            t.astigmatism += plate * q * q;
            t.distortion += plate * q * q * q;
        }
        const double dColour = colourOf(s.mediumAfter) / n1 - (k == 0 ? 0.0 : colourOf(lens.surfaces[k - 1].mediumAfter) / n0);
        t.axialColour = refraction * y * dColour;
        t.lateralColour = refractionBar * y * dColour;
        out.surfaces.push_back(t);
        out.total.spherical += t.spherical;
        out.total.coma += t.coma;
        out.total.astigmatism += t.astigmatism;
        out.total.petzval += t.petzval;
        out.total.distortion += t.distortion;
        out.total.axialColour += t.axialColour;
        out.total.lateralColour += t.lateralColour;
    }
    return out;
}

}  // namespace lenslab
