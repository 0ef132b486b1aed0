#include "LensText.h"

#include <cstdio>
#include <string>

#include "firstorder/Aperture.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

void line(std::string& out, const char* label, double v, const char* note = "") {
    char b[160];
    std::snprintf(b, sizeof b, *note ? "  %-28s %12.4f mm  %s\n" : "  %-28s %12.4f mm\n", label, v, note);
    out += b;
}

std::string surfaceTable(const LensSystem& lens) {
    char b[256];
    std::string out = "Surfaces\n    #        z (mm)    radius (mm)        N   diameter (mm)  glass\n";
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const Surface& s = lens.surfaces[i];
        std::string notes = s.mediumAfter.name.empty() ? "" : "  " + s.mediumAfter.name;
        if (s.isStop) notes += "  stop";
        if (s.mirror) notes += "  mirror";
        if (s.conic != 0) notes += "  conic " + formatNumber(s.conic);
        if (s.isAspheric()) notes += "  asphere";
        if (s.obscurationRadius > 0) notes += "  obscuration " + formatNumber(2 * s.obscurationRadius) + " mm";
        if (!s.coating.bare()) notes += "  coat " + s.coating.text + (s.coating.isDefault ? " (default)" : "");
        if (!s.form.isEvenAsphere()) notes += std::string("  ") + surfaceKindName(s.form.kind);
        if (s.clearShape) notes += std::string("  ") + apertureKindName(s.clearShape->kind) + " aperture";
        if (s.frame)
            notes += "  decentre " + formatNumber(s.frame->decentre[0]) + "," + formatNumber(s.frame->decentre[1]) + "," +
                     formatNumber(s.frame->decentre[2]) + " mm tilt " + formatNumber(s.frame->tiltDegrees[0]) + "," +
                     formatNumber(s.frame->tiltDegrees[1]) + "," + formatNumber(s.frame->tiltDegrees[2]) + " deg";
        std::snprintf(b, sizeof b, "  %3zu  %12.4f  %13.4f  %7.4f  %14.4f", i + 1, s.z, s.radius, s.indexAfter,
                      2 * s.apertureRadius);
        out += b + notes + "\n";
    }
    return out;
}

}  // namespace

std::string lensAnalysisText(const LensAnalysis& a) {
    const FirstOrder& fo = a.firstOrder;
    std::string out;
    char b[256];
    if (a.lens.format == "zmx" || a.lens.format == "seq")
        std::snprintf(b, sizeof b, "%s  (%zu surfaces, %s file)\n", a.lens.name.c_str(), a.lens.surfaces.size(),
                      a.lens.format == "zmx" ? "Zemax" : "Code V");
    else
        std::snprintf(b, sizeof b, "%s  (%zu surfaces, %s layout)\n", a.lens.name.c_str(), a.lens.surfaces.size(),
                      layoutName(a.lens.layout));
    out += b;
    for (const auto& c : a.lens.comments) out += "  # " + c + "\n";
    for (const LensWarning& w : a.lens.warnings)
        out += "  warning" + (w.line > 0 ? " (line " + std::to_string(w.line) + ")" : std::string()) + ": " + w.message + "\n";
    out += "z in mm: origin at the front vertex, +z toward the scene, film at negative z\n";
    std::snprintf(b, sizeof b, "wavelength %.2f nm%s\n\n", a.lens.wavelength,
                  a.lens.isDispersive() ? "" : " (no dispersion: one index per medium)");
    out += b;
    if (a.afocal) {
        out += "Afocal: parallel rays leave parallel (no focal points, f-number or focus)\n";
        out += surfaceTable(a.lens);
        return out;
    }
    out += "First order\n";
    line(out, "effective focal length", fo.efl);
    line(out, "back focal distance", fo.backFocalDistance, "rear vertex to F'");
    if (!a.incomplete.empty()) {
        line(out, "F'  (rear focal point) z", fo.zFPrime);
        line(out, "P'  (rear principal) z", fo.zPPrime);
        out += "\nNo aperture or focus: " + a.incomplete + "\n\n" + surfaceTable(a.lens);
        return out;
    }
    line(out, "front focal distance", fo.frontFocalDistance, "F to front vertex");
    line(out, "F   (front focal point) z", fo.zF);
    line(out, "F'  (rear focal point) z", fo.zFPrime);
    line(out, "P   (front principal) z", fo.zP);
    line(out, "P'  (rear principal) z", fo.zPPrime);
    out += "\nAperture\n";
    std::snprintf(b, sizeof b, "  %-28s %12.4f     (range %s)\n", "f-number", a.fstop, fstopRangeText(a.aperture).c_str());
    out += b;
    line(out, "stop z", a.lens.stop().z);
    line(out, "stop diameter", a.stopDiameter);
    line(out, "stop diameter at widest", a.aperture.stopDiameterMax);
    line(out, "entrance pupil z", a.pupils.entrance.z);
    line(out, "entrance pupil diameter", a.pupils.entrance.diameter);
    line(out, "exit pupil z", a.pupils.exit.z);
    line(out, "exit pupil diameter", a.pupils.exit.diameter);
    out += "\nFocus\n";
    if (a.focus.infinity) out += "  object                              infinity\n";
    else line(out, "object distance", a.focus.objectZ - a.lens.frontZ(), "from the front vertex");
    line(out, "film z, thick lens", a.focus.imageZThick);
    line(out, "film z, exact", a.focus.imageZExact, "least RMS spot on axis");
    line(out, "exact - thick", a.focus.difference);
    const Chromatic& c = a.chromatic;
    out += "\nColour (F 486.13, d 587.56, C 656.27 nm)\n";
    line(out, "EFL at F", c.eflF);
    line(out, "EFL at d", c.eflD);
    line(out, "EFL at C", c.eflC);
    line(out, "image z at F", c.imageZF, "paraxial image of the plane of focus");
    line(out, "image z at d", c.imageZD);
    line(out, "image z at C", c.imageZC);
    line(out, "longitudinal colour", c.longitudinalColour, "image z C - F");
    if (c.lateral) {
        std::snprintf(b, sizeof b, "F - C chief ray at %.2f deg", c.lateral->fieldDegrees);
        line(out, "lateral colour", c.lateral->mm, b);
    } else {
        std::snprintf(b, sizeof b, "  %-28s none: no largest field\n", "lateral colour");
        out += b;
    }
    out += "\nField of view\n";
    if (a.field.largestDegrees)
        std::snprintf(b, sizeof b, "  %-28s %12.4f deg  %s\n", "largest field", *a.field.largestDegrees, a.field.source.c_str());
    else
        std::snprintf(b, sizeof b, "  %-28s %s\n", "largest field", a.field.source.c_str());
    out += b;
    out += "\n" + surfaceTable(a.lens);
    return out;
}

}  // namespace lenslab
