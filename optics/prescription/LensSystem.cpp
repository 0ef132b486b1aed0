#include "prescription/LensSystem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "prescription/GlassCatalog.h"

namespace lenslab {

namespace {

std::string mm(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v << " mm";
    return s.str();
}

// Surfaces i and i+1 must not cross anywhere both exist; touching at a rim is allowed. Light
// travels toward -z (`towardFilm`) or, between an odd number of mirrors, back toward +z.
void checkNoOverlap(const LensSystem& lens, const std::vector<LensTableRow>& rows, int i, bool towardFilm) {
    const Surface& a = lens.surfaces[i];
    const Surface& b = lens.surfaces[i + 1];
    const double hMax = std::min(a.apertureRadius, b.apertureRadius);
    const double tolerance = 1e-9 * std::max(1.0, std::fabs(a.z));
    const double way = towardFilm ? 1.0 : -1.0;
    constexpr int kSamples = 64;
    for (int k = 0; k <= kSamples; ++k) {
        const double h = hMax * k / kSamples;
        const double zA = a.z - sag(a, h), zB = b.z - sag(b, h);
        if (way * (zA - zB) < -tolerance) {
            std::ostringstream msg;
            msg << "surface overlaps the one before it: at height " << mm(h) << " its sag puts it "
                << mm(way * (zB - zA)) << (towardFilm ? " in front of" : " behind") << " line " << rows[i].line
                << "'s surface (gap " << mm(way * (a.z - b.z)) << ")";
            throw LensTableError(lens.name, rows[i + 1].line, msg.str());
        }
    }
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// The medium on the film side of a row: a catalog glass, a model glass (N and Vd), or the plain index.
Medium mediumOf(const LensTable& table, const LensTableRow& r) {
    if (!r.glass.empty()) {
        const GlassLookup found = findGlass(r.glass, table.catalogs);
        if (!found.glass) {
            if (r.glass.size() > kMaxGlassNameLength)
                throw LensTableError(table.name, r.line, "a glass name of " + std::to_string(r.glass.size()) +
                                                             " characters: catalog names have at most " +
                                                             std::to_string(kMaxGlassNameLength));
            std::string msg = "unknown glass '" + r.glass + "' (searched " + joined(found.searched) + ")";
            if (!found.suggestions.empty()) msg += "; nearest: " + joined(found.suggestions);
            msg += "; give its nd and Vd instead to use a model glass";
            throw LensTableError(table.name, r.line, msg);
        }
        // A table's N that disagrees with the glass named beside it is a typo in one of them. A .zmx
        // file's GLAS line carries whatever nd its writer left there (often a placeholder): its name rules.
        constexpr double kIndexTolerance = 2e-3;
        if (table.format != "zmx" && r.index > 1 && std::fabs(r.index - found.glass->nd) > kIndexTolerance) {
            std::ostringstream msg;
            msg.precision(6);
            msg << "N " << r.index << " contradicts " << found.glass->name << " (" << found.glass->catalog
                << "), whose nd is " << found.glass->nd << ": correct the index or the glass name";
            throw LensTableError(table.name, r.line, msg.str());
        }
        return *found.glass;
    }
    if (r.abbe > 0) {
        if (!(r.index > 1))
            throw LensTableError(table.name, r.line, "an Abbe number needs a refractive index above 1 beside it");
        return modelGlass(r.index, r.abbe);
    }
    return r.index == 0 || r.index == 1 ? air() : constantIndex(r.index);
}

void checkSagDefined(const LensTable& table, const LensTableRow& r, const Surface& s) {
    const double limit = sagDomainRadius(s);
    if (s.apertureRadius <= limit) return;
    std::ostringstream msg;
    msg.precision(6);
    if (s.conic == 0)
        msg << "diameter " << mm(2 * s.apertureRadius) << " is larger than the sphere of radius "
            << mm(std::fabs(s.radius)) << " allows (at most " << mm(2 * limit) << ")";
    else
        msg << "clear diameter " << mm(2 * s.apertureRadius) << " reaches past where the conic surface (radius "
            << mm(s.radius) << ", conic " << s.conic << ") is defined: at most " << mm(2 * limit);
    throw LensTableError(table.name, r.line, msg.str());
}

}  // namespace

bool Surface::isAspheric() const {
    return std::any_of(aspheric.begin(), aspheric.end(), [](double a) { return a != 0; });
}

bool LensSystem::isDispersive() const {
    return std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return lenslab::isDispersive(s.mediumAfter); });
}

double LensSystem::zDirectionAfter(int i) const {
    double direction = -1;
    for (int k = 0; k <= i; ++k)
        if (surfaces[k].mirror) direction = -direction;
    return direction;
}

bool LensSystem::hasMirrors() const {
    return std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return s.mirror; });
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
    lens.name = table.name;
    lens.comments = table.comments;
    lens.layout = table.layout;
    lens.format = table.format;
    lens.wavelength = lens.primaryWavelength = table.primaryWavelength;
    lens.designFNumber = table.designFNumber;
    lens.entrancePupilDiameter = table.entrancePupilDiameter;
    const auto& rows = table.rows;
    const int n = static_cast<int>(rows.size());

    int stops = 0;
    double z = 0;
    for (int i = 0; i < n; ++i) {
        const LensTableRow& r = rows[i];
        if (table.layout == TableLayout::GapBefore) z -= r.gap;
        else if (i > 0) z -= rows[i - 1].gap;
        Surface s;
        s.z = z;
        s.radius = r.radius;
        s.curvature = r.radius == 0 ? 0.0 : 1.0 / r.radius;
        s.conic = r.conic;
        s.aspheric = r.aspheric;
        s.mirror = r.mirror;
        // A mirror sends the ray back through the medium it came from.
        s.mediumAfter = r.mirror ? (i == 0 ? air() : lens.surfaces[i - 1].mediumAfter) : mediumOf(table, r);
        s.apertureRadius = 0.5 * r.diameter;
        s.obscurationRadius = 0.5 * r.obscurationDiameter;
        s.isStop = r.isStop();
        s.line = r.line;
        if (s.isStop) {
            if (++stops > 1)
                throw LensTableError(table.name, r.line,
                                     "a second aperture stop; the first is on line " +
                                         std::to_string(rows[lens.stopIndex].line));
            lens.stopIndex = i;
        }
        if (s.obscurationRadius >= s.apertureRadius)
            throw LensTableError(table.name, r.line, "the central obscuration (" + mm(r.obscurationDiameter) +
                                                         ") covers the whole clear diameter (" + mm(r.diameter) + ")");
        checkSagDefined(table, r, s);
        lens.surfaces.push_back(s);
    }
    if (stops == 0)
        throw LensTableError(table.name, rows.front().line,
                             table.format == "zmx" ? "no aperture stop: no surface is marked STOP"
                                                   : "no aperture stop: one row must have radius 0 and N 0");
    lens = atWavelength(lens, lens.wavelength);
    if (lens.surfaces.back().indexAfter != 1.0)
        throw LensTableError(table.name, rows.back().line,
                             "the last surface must leave the ray in air (N 0 or 1) before the film");
    bool towardFilm = true;
    for (int i = 0; i + 1 < n; ++i) {
        towardFilm ^= lens.surfaces[i].mirror;
        checkNoOverlap(lens, rows, i, towardFilm);
    }
    if (!towardFilm ^ lens.surfaces.back().mirror)
        throw LensTableError(table.name, rows.back().line,
                             "after the last surface the light travels back toward the scene: a camera lens needs an "
                             "even number of mirrors");
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
