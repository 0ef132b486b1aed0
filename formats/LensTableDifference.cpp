#include "LensTableDifference.h"

#include <cmath>

#include "prescription/LensSystem.h"
#include "prescription/NumberText.h"
#include "trace/ExactTrace.h"

namespace lenslab {

namespace {

// Collects the first difference; later comparisons are skipped once one is found.
struct Comparison {
    std::optional<std::string> found;

    void text(const std::string& what, const std::string& a, const std::string& b) {
        if (!found && a != b) found = what + ": '" + a + "' / '" + b + "'";
    }
    void number(const std::string& what, double a, double b) {
        // Exact, and NaN never equal; an infinite object distance on both sides is.
        if (!found && !(a == b)) found = what + ": " + formatNumber(a, 17) + " / " + formatNumber(b, 17);
    }
    void flag(const std::string& what, bool a, bool b) {
        if (!found && a != b) found = what + ": " + (a ? "yes" : "no") + " / " + (b ? "yes" : "no");
    }
    template <class T, std::size_t N>
    void numbers(const std::string& what, const std::array<T, N>& a, const std::array<T, N>& b) {
        for (std::size_t i = 0; i < N; ++i) number(what + " " + std::to_string(i + 1), a[i], b[i]);
    }
    void numbers(const std::string& what, const std::vector<double>& a, const std::vector<double>& b) {
        number(what + " count", double(a.size()), double(b.size()));
        for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) number(what + " " + std::to_string(i + 1), a[i], b[i]);
    }
    void optionalNumber(const std::string& what, const std::optional<double>& a, const std::optional<double>& b) {
        flag(what + " given", a.has_value(), b.has_value());
        if (a && b) number(what, *a, *b);
    }
    void frame(const std::string& what, const std::optional<FrameChange>& a, const std::optional<FrameChange>& b) {
        flag(what + " given", a.has_value(), b.has_value());
        if (!a || !b) return;
        numbers(what + " decentre", a->decentre, b->decentre);
        numbers(what + " tilt", a->tiltDegrees, b->tiltDegrees);
        number(what + " mode", double(a->mode), double(b->mode));
        number(what + " order", double(a->order), double(b->order));
    }
    void aperture(const std::string& what, const std::optional<SurfaceAperture>& a, const std::optional<SurfaceAperture>& b) {
        flag(what + " given", a.has_value(), b.has_value());
        if (!a || !b) return;
        text(what + " kind", apertureKindName(a->kind), apertureKindName(b->kind));
        number(what + " half width x", a->halfWidthX, b->halfWidthX);
        number(what + " half width y", a->halfWidthY, b->halfWidthY);
        number(what + " centre x", a->centreX, b->centreX);
        number(what + " centre y", a->centreY, b->centreY);
    }
    void row(const std::string& what, const LensTableRow& a, const LensTableRow& b) {
        number(what + " radius", a.radius, b.radius);
        number(what + " gap", a.gap, b.gap);
        number(what + " index", a.index, b.index);
        number(what + " diameter", a.diameter, b.diameter);
        flag(what + " stop", a.stop, b.stop);
        text(what + " glass", a.glass, b.glass);
        text(what + " glass catalog", a.glassCatalog, b.glassCatalog);
        number(what + " Abbe number", a.abbe, b.abbe);
        number(what + " conic", a.conic, b.conic);
        numbers(what + " aspheric term", a.aspheric, b.aspheric);
        flag(what + " mirror", a.mirror, b.mirror);
        number(what + " obscuration diameter", a.obscurationDiameter, b.obscurationDiameter);
        text(what + " surface kind", surfaceKindName(a.form.kind), surfaceKindName(b.form.kind));
        numbers(what + " form term", a.form.terms, b.form.terms);
        number(what + " form term count", a.form.termCount, b.form.termCount);
        number(what + " normalisation radius", a.form.normalisationRadius, b.form.normalisationRadius);
        aperture(what + " clear aperture", a.clearShape, b.clearShape);
        aperture(what + " obscuration", a.obscurationShape, b.obscurationShape);
        frame(what + " frame", a.frame, b.frame);
        flag(what + " coordinate break", a.coordinateBreak, b.coordinateBreak);
        flag(what + " automatic diameter", a.automaticDiameter, b.automaticDiameter);
        text(what + " name", a.name, b.name);
        text(what + " coating", a.coating, b.coating);
    }
};

// Within `tolerance`: for the built lenses, whose numbers come through different arithmetic.
struct NearComparison {
    double tolerance;
    std::optional<std::string> found;
    void number(const std::string& what, double a, double b) {
        if (!found && !(std::fabs(a - b) <= tolerance * std::max(1.0, std::fabs(a))))
            found = what + ": " + formatNumber(a, 17) + " / " + formatNumber(b, 17);
    }
    void vector(const std::string& what, const Vec3& a, const Vec3& b) {
        number(what + " x", a.x, b.x);
        number(what + " y", a.y, b.y);
        number(what + " z", a.z, b.z);
    }
};

}  // namespace

std::optional<std::string> builtLensDifference(const LensTable& a, const LensTable& b, double tolerance) {
    const LensSystem x = buildLensSystem(a), y = buildLensSystem(b);
    NearComparison c{tolerance, std::nullopt};
    c.number("surface count", double(x.surfaces.size()), double(y.surfaces.size()));
    for (std::size_t i = 0; i < x.surfaces.size() && i < y.surfaces.size(); ++i) {
        const Surface &s = x.surfaces[i], &t = y.surfaces[i];
        const std::string what = "surface " + std::to_string(i + 1);
        c.number(what + " z", s.z, t.z);
        c.number(what + " radius", s.radius, t.radius);
        c.number(what + " conic", s.conic, t.conic);
        c.number(what + " semi-diameter", s.apertureRadius, t.apertureRadius);
        c.number(what + " index after", s.indexAfter, t.indexAfter);
        c.number(what + " stop", s.isStop, t.isStop);
        c.number(what + " mirror", s.mirror, t.mirror);
    }
    // 7 heights across the front surface's semi-diameter, at 5 angles up to 10 degrees in y and x.
    const Surface& front = x.surfaces.front();
    for (int h = -3; h <= 3; ++h)
        for (int k = -2; k <= 2; ++k) {
            const double angle = k * 5 * M_PI / 180, height = h * front.apertureRadius / 4;
            const Ray ray{{height / 3, height, front.z + 1}, {std::sin(angle) / 2, std::sin(angle), -std::sqrt(1 - 1.25 * std::sin(angle) * std::sin(angle))}};
            const TraceResult p = traceRay(x, ray, TraceDirection::SceneToFilm), q = traceRay(y, ray, TraceDirection::SceneToFilm);
            const std::string what = "ray " + std::to_string(h) + "/" + std::to_string(k);
            c.number(what + " blocked at surface", p.ok() ? -1 : p.surface, q.ok() ? -1 : q.surface);
            if (p.ok() && q.ok()) {
                c.vector(what + " leaving at", p.ray.origin, q.ray.origin);
                c.vector(what + " leaving along", p.ray.direction, q.ray.direction);
            }
        }
    return c.found;
}

std::optional<std::string> lensTableDifference(const LensTable& a, const LensTable& b) {
    Comparison c;
    c.number("comment count", double(a.comments.size()), double(b.comments.size()));
    for (std::size_t i = 0; i < a.comments.size() && i < b.comments.size(); ++i)
        c.text("comment " + std::to_string(i + 1), a.comments[i], b.comments[i]);
    c.text("layout", layoutName(a.layout), layoutName(b.layout));
    c.number("primary wavelength", a.primaryWavelength, b.primaryWavelength);
    c.numbers("wavelength", a.wavelengths, b.wavelengths);
    c.numbers("wavelength weight", a.wavelengthWeights, b.wavelengthWeights);
    c.number("catalog count", double(a.catalogs.size()), double(b.catalogs.size()));
    for (std::size_t i = 0; i < a.catalogs.size() && i < b.catalogs.size(); ++i)
        c.text("catalog " + std::to_string(i + 1), a.catalogs[i], b.catalogs[i]);
    c.optionalNumber("f-number", a.designFNumber, b.designFNumber);
    c.optionalNumber("entrance pupil diameter", a.entrancePupilDiameter, b.entrancePupilDiameter);
    c.optionalNumber("object numerical aperture", a.objectNumericalAperture, b.objectNumericalAperture);
    c.text("field type", fieldTypeName(a.fields.type), fieldTypeName(b.fields.type));
    c.number("field count", double(a.fields.points.size()), double(b.fields.points.size()));
    for (std::size_t i = 0; i < a.fields.points.size() && i < b.fields.points.size(); ++i) {
        const std::string what = "field " + std::to_string(i + 1);
        c.number(what + " x", a.fields.points[i].x, b.fields.points[i].x);
        c.number(what + " y", a.fields.points[i].y, b.fields.points[i].y);
        c.number(what + " weight", a.fields.points[i].weight, b.fields.points[i].weight);
    }
    c.number("object distance", a.objectDistance, b.objectDistance);
    c.frame("image frame", a.imageFrame, b.imageFrame);
    c.number("substitution count", double(a.substitutes.size()), double(b.substitutes.size()));
    c.number("row count", double(a.rows.size()), double(b.rows.size()));
    for (std::size_t i = 0; i < a.rows.size() && i < b.rows.size(); ++i) c.row("row " + std::to_string(i + 1), a.rows[i], b.rows[i]);
    return c.found;
}

}  // namespace lenslab
