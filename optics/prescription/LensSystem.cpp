#include "prescription/LensSystem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "prescription/AutomaticApertures.h"
#include "prescription/EdgeOverlap.h"
#include "prescription/FormSag.h"
#include "prescription/NumberText.h"
#include "prescription/RowMedium.h"

namespace lenslab {

namespace {

void checkSagDefined(const LensTable& table, const LensTableRow& r, const Surface& s) {
    const double limit = sagDomainRadius(s);
    if (s.apertureRadius <= limit) return;
    std::ostringstream msg;
    msg.precision(6);
    if (s.conic == 0)
        msg << "diameter " << formatMillimetres(2 * s.apertureRadius) << " is larger than the sphere of radius "
            << formatMillimetres(std::fabs(s.radius)) << " allows (at most " << formatMillimetres(2 * limit) << ")";
    else
        msg << "clear diameter " << formatMillimetres(2 * s.apertureRadius) << " reaches past where the conic surface (radius "
            << formatMillimetres(s.radius) << ", conic " << s.conic << ") is defined: at most " << formatMillimetres(2 * limit);
    throw LensTableError(table.name, r.line, msg.str());
}

void checkForm(const LensTable& table, const LensTableRow& r) {
    const SurfaceForm& f = r.form;
    if (f.termCount < 0 || f.termCount > kFormTerms)
        throw LensTableError(table.name, r.line, "a surface form has at most " + std::to_string(kFormTerms) + " terms");
    const bool q = f.kind == SurfaceKind::Qbfs || f.kind == SurfaceKind::Qcon;
    if (q && !(f.normalisationRadius > 0 && std::isfinite(f.normalisationRadius)))
        throw LensTableError(table.name, r.line, std::string(surfaceKindName(f.kind)) +
                                                     " needs a positive normalisation radius, found " +
                                                     formatMillimetres(f.normalisationRadius));
    if (f.kind == SurfaceKind::Qbfs && r.conic != 0)
        throw LensTableError(table.name, r.line, "a Qbfs surface departs from a sphere (Forbes 2007): its conic must be 0");
}

// The surface a row describes, before its medium and its place among the others are known.
Surface surfaceOf(const LensTableRow& r, double z) {
    Surface s;
    s.z = z;
    s.radius = r.radius;
    s.curvature = r.radius == 0 ? 0.0 : 1.0 / r.radius;
    s.conic = r.conic;
    s.aspheric = r.aspheric;
    s.form = r.form;
    s.mirror = r.mirror;
    s.apertureRadius = 0.5 * r.diameter;
    s.automaticAperture = r.automaticDiameter;
    s.obscurationRadius = 0.5 * r.obscurationDiameter;
    s.clearShape = r.clearShape;
    s.obscurationShape = r.obscurationShape;
    // A shaped clear aperture is held by the circle that reaches its far corner.
    if (r.clearShape) s.apertureRadius = std::max(s.apertureRadius, r.clearShape->reach());
    s.isStop = r.isStop();
    s.line = r.line;
    s.name = r.name;
    return s;
}

// Coordinates mirrored across the plane z = z0 (an odd number of mirrors: the image space turned so
// the light leaves toward the film at -z like every other lens's).
RigidMotion mirrorAcross(double z0) {
    RigidMotion m;
    m.rotation = {1, 0, 0, 0, 1, 0, 0, 0, -1};
    m.shift = {0, 0, 2 * z0};
    return m;
}

// The .seq and .zmx figures the table keeps for the analysis above.
void copyFileFacts(const LensTable& table, LensSystem& lens) {
    lens.name = table.name;
    lens.comments = table.comments;
    lens.layout = table.layout;
    lens.format = table.format;
    lens.wavelength = lens.primaryWavelength = table.primaryWavelength;
    lens.designFNumber = table.designFNumber;
    lens.entrancePupilDiameter = table.entrancePupilDiameter;
    lens.objectNumericalAperture = table.objectNumericalAperture;
    lens.wavelengths = table.wavelengths;
    lens.wavelengthWeights = table.wavelengthWeights;
    lens.fields = table.fields;
    lens.objectDistance = table.objectDistance;
    lens.warnings = table.warnings;
}

// The row's coating, or the default for a real lens: MgF2 on surfaces between air and glass.
Coating coatingOf(const LensTable& table, const LensTableRow& r, const LensSystem& lens, int i) {
    const Surface& s = lens.surfaces[i];
    if (!r.coating.empty()) {
        if (s.mirror) throw LensTableError(table.name, r.line, "coating '" + r.coating + "' on a mirror: only refracting surfaces take an anti-reflection coating");
        try {
            return parseCoating(r.coating);
        } catch (const CoatingError& e) {
            throw LensTableError(table.name, r.line, e.what());
        }
    }
    const bool airBefore = lens.indexBefore(i) == 1.0, airAfter = s.indexAfter == 1.0;
    if (s.mirror || airBefore == airAfter) return Coating{};
    Coating c = parseCoating(kDefaultCoatingText);
    c.isDefault = true;
    return c;
}

}  // namespace

bool Surface::isAspheric() const {
    return std::any_of(aspheric.begin(), aspheric.end(), [](double a) { return a != 0; }) || !form.isEvenAsphere();
}

double Surface::vertexCurvature() const {
    switch (form.kind) {
        case SurfaceKind::EvenAsphere: return curvature + 2 * aspheric[0];
        case SurfaceKind::OddAsphere: return curvature + 2 * form.terms[1];
        case SurfaceKind::Qcon: return curvature;
        case SurfaceKind::Toroidal: return curvature + 2 * form.terms[1];  // in the y-z plane
        case SurfaceKind::Qbfs: {
            // x (1 - x) phi sum a_m Q_m(x) ~ (r^2 / r_norm^2) sum a_m Q_m(0) near the vertex.
            double sum = 0, slope = 0;
            qSum(FormConstants<double>::of(form), 0.0, sum, slope);
            return curvature + 2 * sum / (form.normalisationRadius * form.normalisationRadius);
        }
    }
    return curvature;
}

bool LensSystem::isDispersive() const {
    return std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return lenslab::isDispersive(s.mediumAfter); });
}

// The axis's direction carried through every surface's motions, each mirror reflecting it about
// its vertex normal (the surface's z): mirrors turn the light back along z, and so do motions that
// turn z around (the mirrored image space of an odd number of mirrors). The motions' product
// decides, not each one alone: two tilts of 60 and 45 degrees turn z around as one of 105 does.
double LensSystem::zDirectionAfter(int i) const {
    std::array<double, 3> axis{0, 0, -1};
    for (int k = 0; k <= i; ++k) {
        const Surface& s = surfaces[k];
        axis = s.before.applyToDirection(axis);
        if (s.mirror) axis[2] = -axis[2];
        axis = s.after.applyToDirection(axis);
    }
    return axis[2] > 0 ? 1 : -1;
}

bool LensSystem::hasMirrors() const {
    return std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return s.mirror; });
}

bool LensSystem::hasMovedSurfaces() const {
    return std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return s.isMoved(); });
}

bool LensSystem::isRotationallySymmetric() const {
    return !decentred && std::none_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return s.needsGeneralStep(); });
}

double sag(const Surface& s, double h) {
    // Written so that flat surfaces (curvature 0) and huge radii stay exact.
    const double c = s.curvature, rho = h * h;
    double u = 1.0 - (1.0 + s.conic) * c * c * rho;
    // At the domain's rim (a hemisphere's edge) rounding may leave u a few ulp below 0.
    if (u < 0) {
        if (u < -1e-12) return std::numeric_limits<double>::quiet_NaN();
        u = 0;
    }
    if (s.form.kind == SurfaceKind::Toroidal) {  // the y-z profile
        double value, gx, gy, unused;
        toroidSag(FormConstants<double>::of(s.form), c, 1.0 + s.conic, 0.0, h, value, gx, gy, unused);
        return value;
    }
    if (!s.form.isEvenAsphere()) {
        double value, g, unused;
        formSag(FormConstants<double>::of(s.form), c, 1.0 + s.conic, rho, value, g, unused);
        return value;
    }
    double poly = 0;
    for (int i = kAsphericTerms - 1; i >= 0; --i) poly = poly * rho + s.aspheric[i];
    return c * rho / (1.0 + std::sqrt(u)) + poly * rho;
}

double sagDomainRadius(const Surface& s) {
    const double k1 = (1.0 + s.conic) * s.curvature * s.curvature;
    return k1 > 0 ? 1.0 / std::sqrt(k1) : std::numeric_limits<double>::infinity();
}

LensSystem atWavelength(const LensSystem& lens, double wavelength) {
    LensSystem out = lens;
    out.wavelength = wavelength;
    for (Surface& s : out.surfaces) s.indexAfter = refractiveIndex(s.mediumAfter, wavelength);
    return out;
}

LensSystem buildLensSystem(const LensTable& table) {
    LensSystem lens;
    copyFileFacts(table, lens);
    const auto& rows = table.rows;
    const int n = static_cast<int>(rows.size());

    int stops = 0;
    double z = 0;
    RigidMotion pending;  // coordinate breaks not yet met by a surface
    std::vector<const LensTableRow*> surfaceRows;  // each surface's row (coordinate breaks have none)
    Medium medium = air();
    std::set<std::string> warnedMedia;  // each glass's data checked against the wavelengths once
    for (int i = 0; i < n; ++i) {
        const LensTableRow& r = rows[i];
        if (table.layout == TableLayout::GapBefore) z -= r.gap;
        else if (i > 0) z -= rows[i - 1].gap;
        lens.decentred |= r.frame.has_value();
        if (r.coordinateBreak) {
            if (r.frame) pending = pending.then(surfaceMotions(*r.frame, z).before);
            continue;
        }
        checkForm(table, r);
        Surface s = surfaceOf(r, z);
        // A mirror sends the ray back through the medium it came from.
        s.mediumAfter = r.mirror ? medium : rowMedium(table, r, lens.warnings);
        if (!r.mirror && warnedMedia.insert(s.mediumAfter.name + "/" + s.mediumAfter.catalog).second)
            if (auto beyond = wavelengthsBeyondData(table, r, s.mediumAfter)) lens.warnings.push_back({r.line, *beyond});
        medium = s.mediumAfter;
        s.frame = r.frame;
        if (r.frame) {
            const SurfaceMotions m = surfaceMotions(*r.frame, z);
            s.before = m.before;
            s.after = m.after;
        }
        s.before = pending.then(s.before);
        pending = RigidMotion{};
        if (s.isStop) {
            if (++stops > 1)
                throw LensTableError(table.name, r.line,
                                     "a second aperture stop; the first is on line " +
                                         std::to_string(lens.surfaces[lens.stopIndex].line));
            lens.stopIndex = static_cast<int>(lens.surfaces.size());
        }
        if (!s.automaticAperture && s.obscurationRadius >= s.apertureRadius)
            throw LensTableError(table.name, r.line, "the central obscuration (" + formatMillimetres(r.obscurationDiameter) +
                                                         ") covers the whole clear diameter (" + formatMillimetres(r.diameter) + ")");
        if (!s.automaticAperture && !s.clearShape) checkSagDefined(table, r, s);
        lens.surfaces.push_back(s);
        surfaceRows.push_back(&r);
    }
    if (lens.surfaces.empty())
        throw LensTableError(table.name, rows.empty() ? 0 : rows.front().line, "no surfaces: only coordinate breaks");
    if (stops == 0)
        throw LensTableError(table.name, rows.front().line,
                             table.format == "table" ? "no aperture stop: one row must have radius 0 and N 0"
                                                     : "no aperture stop: no surface is marked STOP");
    lens.surfaces.back().after = lens.surfaces.back().after.then(pending);
    double imageZ = z - (table.layout == TableLayout::GapAfter ? rows.back().gap : 0);
    lens = atWavelength(lens, lens.wavelength);
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i)
        lens.surfaces[i].coating = coatingOf(table, *surfaceRows[i], lens, static_cast<int>(i));
    if (lens.surfaces.back().indexAfter != 1.0)
        throw LensTableError(table.name, rows.back().line,
                             "the last surface must leave the ray in air (N 0 or 1) before the film");
    // After an odd number of mirrors the light runs back toward the scene: the image space is
    // mirrored so that it leaves toward the film at -z.
    if (lens.zDirectionAfter(static_cast<int>(lens.surfaces.size()) - 1) > 0) {
        Surface& rear = lens.surfaces.back();
        rear.after = rear.after.then(mirrorAcross(rear.z));
        imageZ = 2 * rear.z - imageZ;
    }
    if (table.imageFrame) lens.imageFrame = surfaceMotions(*table.imageFrame, imageZ).before;
    lens.decentred |= table.imageFrame.has_value();
    setAutomaticApertures(lens, table);
    clipOverlappingEdges(lens);
    return lens;
}

LensSystem loadLensSystem(const std::string& path, std::optional<TableLayout> layout) {
    return buildLensSystem(readLensTable(path, layout));
}

LensSystem withStopDiameter(const LensSystem& lens, double diameter) {
    LensSystem out = lens;
    out.surfaces[out.stopIndex].apertureRadius = 0.5 * diameter;
    return out;
}

}  // namespace lenslab
