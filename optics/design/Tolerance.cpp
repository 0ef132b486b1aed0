#include "design/Tolerance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "prescription/LensSystem.h"
#include "prescription/NumberText.h"
#include "prescription/RowMedium.h"

namespace lenslab {

namespace {

constexpr double kTestWavelengthMm = 632.8e-6;  // fringes are counted in the HeNe light of the test plate

struct ToleranceKindInfo {
    ToleranceKind kind;
    const char* name;
    const char* unit;
};

constexpr ToleranceKindInfo kToleranceKinds[] = {
    {ToleranceKind::Radius, "radius", ""},
    {ToleranceKind::Power, "power", " fringes"},
    {ToleranceKind::Astigmatism, "astigmatism", " fringes"},
    {ToleranceKind::Thickness, "thickness", " mm"},
    {ToleranceKind::DecentreX, "decentre_x", " mm"},
    {ToleranceKind::DecentreY, "decentre_y", " mm"},
    {ToleranceKind::TiltX, "tilt_x", " deg"},
    {ToleranceKind::TiltY, "tilt_y", " deg"},
    {ToleranceKind::ElementDecentreX, "element_decentre_x", " mm"},
    {ToleranceKind::ElementDecentreY, "element_decentre_y", " mm"},
    {ToleranceKind::ElementTiltX, "element_tilt_x", " deg"},
    {ToleranceKind::ElementTiltY, "element_tilt_y", " deg"},
    {ToleranceKind::Index, "index", ""},
    {ToleranceKind::Abbe, "abbe", ""},
};

const ToleranceKindInfo& info(ToleranceKind kind) {
    for (const ToleranceKindInfo& k : kToleranceKinds)
        if (k.kind == kind) return k;
    return kToleranceKinds[0];
}

bool isElementKind(ToleranceKind k) {
    return k == ToleranceKind::ElementDecentreX || k == ToleranceKind::ElementDecentreY || k == ToleranceKind::ElementTiltX ||
           k == ToleranceKind::ElementTiltY;
}

bool isGlassKind(ToleranceKind k) { return k == ToleranceKind::Index || k == ToleranceKind::Abbe; }

bool hasGlassAfter(const LensTableRow& r) { return !r.mirror && (!r.glass.empty() || r.index > 1); }

// The row's frame change (a decentre and return), created on first use.
FrameChange& frameOf(LensTableRow& r, FrameMode mode) {
    if (!r.frame) {
        r.frame = FrameChange{};
        r.frame->mode = mode;
    }
    return *r.frame;
}

// The medium after a row with nd moved by dn and Vd by dv: model glasses and plain indices change
// their numbers; a catalog glass becomes a table of its indices so moved, in place of its name.
void perturbGlass(LensTable& table, int row, double dn, double dv) {
    LensTableRow& r = table.rows[row];
    if (r.glass.empty()) {
        r.index += dn;
        if (r.abbe > 0) r.abbe += dv;
        return;
    }
    std::vector<LensWarning> ignored;
    const Medium m = rowMedium(table, r, ignored);
    // n' = nd + dn + (n - nd) s: nd moves by dn, and s scales nF - nC so that Vd becomes Vd + dv.
    const double nd = refractiveIndex(m, kWavelengthD), vd = abbeNumber(m);
    const double scale = vd > 0 ? (nd + dn - 1) / (nd - 1) * vd / (vd + dv) : 1.0;
    std::vector<std::array<double, 2>> pairs;
    for (double nm = 360; nm <= 830; nm += 5) pairs.push_back({nm, nd + dn + (refractiveIndex(m, nm) - nd) * scale});
    const std::string name = m.name + "~" + std::to_string(row + 1);
    table.substitutes.push_back({name, "", "", tabulatedMedium(name, pairs), "as built"});
    r.glass = name;
    r.glassCatalog.clear();
}

// The curvature the fringes of sag at the rim of a clear semi-diameter h add (sag c h^2 / 2).
double fringeCurvature(double fringes, double h) { return h > 0 ? fringes * kTestWavelengthMm / (h * h) : 0.0; }

// Moves rows first..last (a gap-after table) as one rigid element about the first's vertex:
// a coordinate break there, the element, the way back along its axis to the pivot, the inverse
// break (Zemax's order 1 with the signs reversed undoes order 0 exactly), and on to the next surface.
void insertElementMotion(LensTable& table, int first, int last, std::array<double, 2> decentre, std::array<double, 2> tilt) {
    double length = 0;
    for (int i = first; i < last; ++i) length += table.rows[i].gap;
    LensTableRow forward;
    forward.coordinateBreak = true;
    forward.line = table.rows[first].line;
    forward.frame = FrameChange{{decentre[0], decentre[1], 0}, {tilt[0], tilt[1], 0}, FrameMode::Basic, TiltOrder::DecentreThenTilt};
    LensTableRow back = forward;
    back.line = table.rows[last].line;
    back.frame = FrameChange{{-decentre[0], -decentre[1], 0}, {-tilt[0], -tilt[1], 0}, FrameMode::Basic, TiltOrder::TiltThenDecentre};
    back.gap = length + table.rows[last].gap;
    table.rows[last].gap = -length;
    table.rows.insert(table.rows.begin() + last + 1, back);
    table.rows.insert(table.rows.begin() + first, forward);
}

}  // namespace

const char* toleranceKindName(ToleranceKind kind) { return info(kind).name; }

std::optional<ToleranceKind> parseToleranceKind(const std::string& name) {
    for (const ToleranceKindInfo& k : kToleranceKinds)
        if (name == k.name) return k.kind;
    return std::nullopt;
}

std::string describeTolerance(const Tolerance& t) {
    std::string rows = std::to_string(t.row + 1);
    if (isElementKind(t.kind)) rows += "-" + std::to_string(t.lastRow + 1);
    const std::string limit = t.kind == ToleranceKind::Radius ? formatNumber(100 * t.limit) + "%" : formatNumber(t.limit) + info(t.kind).unit;
    return std::string(toleranceKindName(t.kind)) + " " + rows + " +-" + limit;
}

void checkTolerance(const LensTable& table, const Tolerance& t) {
    const int rows = static_cast<int>(table.rows.size());
    const auto refuse = [&](const std::string& why) {
        throw std::invalid_argument("tolerance " + describeTolerance(t) + ": " + why);
    };
    if (t.row < 0 || t.row >= rows) refuse("the lens has rows 1 to " + std::to_string(rows));
    if (!(t.limit >= 0) || !std::isfinite(t.limit)) refuse("its limit must be a finite number at least 0");
    const LensTableRow& r = table.rows[t.row];
    if (r.coordinateBreak) refuse("the row is a coordinate break, not a surface");
    if (isElementKind(t.kind) && (t.lastRow <= t.row || t.lastRow >= rows)) refuse("an element spans two rows or more");
    if (isElementKind(t.kind) && table.layout != TableLayout::GapAfter) refuse("element motions need a gap-after table");
    if (isGlassKind(t.kind) && !hasGlassAfter(r)) refuse("no glass follows the surface");
    if (t.kind == ToleranceKind::Thickness && table.layout == TableLayout::GapBefore && t.row + 1 == rows)
        refuse("a gap-before table has no gap after its last row");
    const bool moves = t.kind == ToleranceKind::DecentreX || t.kind == ToleranceKind::DecentreY || t.kind == ToleranceKind::TiltX ||
                       t.kind == ToleranceKind::TiltY || isElementKind(t.kind);
    if (moves && r.frame) refuse("the surface is already decentred or tilted in the file");
    if ((t.kind == ToleranceKind::Power || t.kind == ToleranceKind::Astigmatism) && !(t.clearRadius > 0))
        refuse("the surface has no clear semi-diameter to count fringes over");
    if (t.kind == ToleranceKind::Astigmatism && (!r.form.isEvenAsphere() || r.conic != 0 || r.aspheric != AsphericCoefficients{}))
        refuse("astigmatism is modelled on spherical and flat surfaces only");
}

std::vector<Tolerance> expandTolerances(const LensTable& table, const ToleranceSpec& spec) {
    const LensSystem lens = buildLensSystem(table);
    std::vector<Tolerance> out;
    const int rows = static_cast<int>(table.rows.size());
    const auto add = [&](ToleranceKind kind, int row, double limit, int lastRow = 0, double clear = 0) {
        if (limit > 0) out.push_back({kind, row, lastRow, limit, clear});
    };
    int surface = 0;
    for (int i = 0; i < rows; ++i) {
        const LensTableRow& r = table.rows[i];
        if (r.coordinateBreak) continue;
        const Surface& s = lens.surfaces[surface++];
        const bool refracts = !r.stop || r.radius != 0 || hasGlassAfter(r) || (i > 0 && hasGlassAfter(table.rows[i - 1]));
        if (r.radius != 0) add(ToleranceKind::Radius, i, spec.radiusFraction);
        if (refracts && !r.stop) {
            add(ToleranceKind::Power, i, spec.powerFringes, 0, s.apertureRadius);
            const bool spherical = r.form.isEvenAsphere() && r.conic == 0 && r.aspheric == AsphericCoefficients{};
            if (spherical) add(ToleranceKind::Astigmatism, i, spec.astigmatismFringes, 0, s.apertureRadius);
        }
        const bool lastGap = i + 1 == rows;
        if (!lastGap) add(ToleranceKind::Thickness, i, spec.thickness);
        if (!r.frame && !r.stop) {
            add(ToleranceKind::DecentreX, i, spec.decentre);
            add(ToleranceKind::DecentreY, i, spec.decentre);
            add(ToleranceKind::TiltX, i, spec.tilt);
            add(ToleranceKind::TiltY, i, spec.tilt);
        }
        if (hasGlassAfter(r)) {
            add(ToleranceKind::Index, i, spec.index);
            add(ToleranceKind::Abbe, i, spec.abbeFraction * lens.surfaces[surface - 1].mediumAfter.vd);
            // An element: glass from this row up to the next row followed by air.
            const bool startsElement = i == 0 || !hasGlassAfter(table.rows[i - 1]);
            int last = i + 1;
            while (last < rows && hasGlassAfter(table.rows[last])) ++last;
            const bool plain = startsElement && last < rows && !r.frame && !table.rows[last].frame &&
                               table.layout == TableLayout::GapAfter;
            if (plain) {
                add(ToleranceKind::ElementDecentreX, i, spec.elementDecentre, last);
                add(ToleranceKind::ElementDecentreY, i, spec.elementDecentre, last);
                add(ToleranceKind::ElementTiltX, i, spec.elementTilt, last);
                add(ToleranceKind::ElementTiltY, i, spec.elementTilt, last);
            }
        }
    }
    return out;
}

LensTable perturbedLens(const LensTable& table, const std::vector<Tolerance>& tolerances, const std::vector<double>& departures) {
    LensTable out = table;
    // Element motions are coordinate breaks inserted around the element once every other departure
    // is in place (the rows' indices hold until then): the element's surfaces follow the first break
    // and the second, after the last surface, undoes it.
    struct ElementMotion {
        int first, last;
        std::array<double, 2> decentre{}, tilt{};
    };
    std::vector<ElementMotion> elements;
    for (std::size_t k = 0; k < tolerances.size(); ++k) {
        const Tolerance& t = tolerances[k];
        const double d = departures[k];
        if (d == 0) continue;
        LensTableRow& r = out.rows[t.row];
        switch (t.kind) {
            case ToleranceKind::Radius:
                if (r.radius != 0) r.radius *= 1 + d;
                break;
            case ToleranceKind::Power: {
                const double c = (r.radius == 0 ? 0.0 : 1 / r.radius) + 2 * fringeCurvature(d, t.clearRadius);
                r.radius = c == 0 ? 0.0 : 1 / c;
                break;
            }
            case ToleranceKind::Astigmatism: {
                // A toroid: the x section keeps the radius (the radius of rotation), the y section's
                // curvature moves, so the two sections' sags differ by d fringes at the rim.
                const double radius = r.radius;
                const double c = (radius == 0 ? 0.0 : 1 / radius) + 2 * fringeCurvature(d, t.clearRadius);
                r.form.kind = SurfaceKind::Toroidal;
                r.form.terms = {};
                r.form.terms[0] = radius;
                r.form.termCount = 1;
                r.radius = c == 0 ? 0.0 : 1 / c;
                break;
            }
            case ToleranceKind::Thickness: gapAfter(out, t.row) += d; break;
            case ToleranceKind::DecentreX: frameOf(r, FrameMode::DecentreAndReturn).decentre[0] += d; break;
            case ToleranceKind::DecentreY: frameOf(r, FrameMode::DecentreAndReturn).decentre[1] += d; break;
            case ToleranceKind::TiltX: frameOf(r, FrameMode::DecentreAndReturn).tiltDegrees[0] += d; break;
            case ToleranceKind::TiltY: frameOf(r, FrameMode::DecentreAndReturn).tiltDegrees[1] += d; break;
            case ToleranceKind::ElementDecentreX:
            case ToleranceKind::ElementDecentreY:
            case ToleranceKind::ElementTiltX:
            case ToleranceKind::ElementTiltY: {
                auto it = std::find_if(elements.begin(), elements.end(), [&](const ElementMotion& e) { return e.first == t.row; });
                if (it == elements.end()) it = elements.insert(elements.end(), ElementMotion{t.row, t.lastRow});
                if (t.kind == ToleranceKind::ElementDecentreX) it->decentre[0] += d;
                if (t.kind == ToleranceKind::ElementDecentreY) it->decentre[1] += d;
                if (t.kind == ToleranceKind::ElementTiltX) it->tilt[0] += d;
                if (t.kind == ToleranceKind::ElementTiltY) it->tilt[1] += d;
                break;
            }
            case ToleranceKind::Index: perturbGlass(out, t.row, d, 0); break;
            case ToleranceKind::Abbe: perturbGlass(out, t.row, 0, d); break;
        }
    }
    // From the last element back, so that earlier rows keep their indices.
    std::sort(elements.begin(), elements.end(), [](const ElementMotion& a, const ElementMotion& b) { return a.first > b.first; });
    for (const ElementMotion& e : elements) insertElementMotion(out, e.first, e.last, e.decentre, e.tilt);
    return out;
}

}  // namespace lenslab
