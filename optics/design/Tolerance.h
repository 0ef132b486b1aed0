#pragma once
// Manufacturing and assembly tolerances (docs/design.md): how far each quantity of an as-built lens
// may lie from the design, and the perturbed lens a set of departures makes. Departures are applied
// to the LensTable, so an as-built lens is analysed, drawn, written and rendered like any other.
#include <optional>
#include <string>
#include <vector>

#include "prescription/LensTable.h"

namespace lenslab {

enum class ToleranceKind {
    Radius,        // fractional change of a surface's radius (flat surfaces: see Power)
    Power,         // irregularity as power: fringes of sag at 632.8 nm over the clear aperture
    Astigmatism,   // irregularity as astigmatism: fringes of cylinder over the clear aperture (a toroid)
    Thickness,     // mm added to the gap after a row
    DecentreX,     // mm, the surface alone (decentre and return)
    DecentreY,
    TiltX,         // degrees about x (the surface alone)
    TiltY,         // degrees about y
    ElementDecentreX,  // mm, rows row..lastRow together about the first's vertex
    ElementDecentreY,
    ElementTiltX,      // degrees about x through the first surface's vertex
    ElementTiltY,
    Index,         // added to the medium after the row at every wavelength
    Abbe,          // added to the medium's Vd (its dispersion scaled, nd kept)
};

const char* toleranceKindName(ToleranceKind kind);  // "radius", "power", "astigmatism", "thickness", "decentre_x", ...
std::optional<ToleranceKind> parseToleranceKind(const std::string& name);

struct Tolerance {
    Tolerance() = default;
    Tolerance(ToleranceKind k, int first, int last, double limitValue, double clear = 0)
        : kind(k), row(first), lastRow(last), limit(limitValue), clearRadius(clear) {}

    ToleranceKind kind = ToleranceKind::Radius;
    int row = 0;       // 0-based
    int lastRow = 0;   // element tolerances: the element's last row
    double limit = 0;  // the departure allowed either way (fraction, fringes, mm, degrees, index, Vd)
    double clearRadius = 0;  // Power, Astigmatism: the surface's clear semi-diameter the fringes are counted over, mm
};

std::string describeTolerance(const Tolerance& t);  // "tilt_x 3 +-0.01 deg"

// The tolerances a designer states once for the whole lens, applied to every surface they fit.
struct ToleranceSpec {
    double radiusFraction = 0;   // every curved surface
    double powerFringes = 0, astigmatismFringes = 0;  // every refracting surface
    double thickness = 0;        // every gap but the image distance
    double decentre = 0;         // every surface, x and y
    double tilt = 0;             // degrees, every surface, about x and y
    double elementDecentre = 0;  // every element (glass between two air gaps), x and y
    double elementTilt = 0;
    double index = 0;            // every glass
    double abbeFraction = 0;     // every glass, a fraction of its Vd
};

// The spec as one tolerance per surface, gap, element and glass it applies to.
std::vector<Tolerance> expandTolerances(const LensTable& table, const ToleranceSpec& spec);

// Throws std::invalid_argument naming the tolerance where it does not apply to the table (a row out
// of range, a glass tolerance on air, a surface that is already decentred).
void checkTolerance(const LensTable& table, const Tolerance& t);

// The table with each tolerance's departure (departures[i] in the tolerance's unit, signed) applied.
LensTable perturbedLens(const LensTable& table, const std::vector<Tolerance>& tolerances, const std::vector<double>& departures);

}  // namespace lenslab
