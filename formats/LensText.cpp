#include "LensText.h"

#include <cstdio>
#include <string>

namespace lenslab {

namespace {

void line(std::string& out, const char* label, double v, const char* note = "") {
    char b[160];
    std::snprintf(b, sizeof b, *note ? "  %-28s %12.4f mm  %s\n" : "  %-28s %12.4f mm\n", label, v, note);
    out += b;
}

}  // namespace

std::string lensAnalysisText(const LensAnalysis& a) {
    const FirstOrder& fo = a.firstOrder;
    std::string out;
    char b[256];
    std::snprintf(b, sizeof b, "%s  (%zu surfaces, %s layout)\n", a.lens.name.c_str(), a.lens.surfaces.size(),
                  layoutName(a.lens.layout));
    out += b;
    for (const auto& c : a.lens.comments) out += "  # " + c + "\n";
    out += "z in mm: origin at the front vertex, +z toward the scene, film at negative z\n\n";
    out += "First order\n";
    line(out, "effective focal length", fo.efl);
    line(out, "back focal distance", fo.backFocalDistance, "rear vertex to F'");
    line(out, "front focal distance", fo.frontFocalDistance, "F to front vertex");
    line(out, "F   (front focal point) z", fo.zF);
    line(out, "F'  (rear focal point) z", fo.zFPrime);
    line(out, "P   (front principal) z", fo.zP);
    line(out, "P'  (rear principal) z", fo.zPPrime);
    out += "\nAperture\n";
    std::snprintf(b, sizeof b, "  %-28s %12.4f     (range f/%.3g to f/%.0f)\n", "f-number", a.fstop,
                  a.aperture.fstopMin, a.aperture.fstopMax);
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
    line(out, "film z, exact (best RMS)", a.focus.imageZExact);
    line(out, "exact - thick", a.focus.difference);
    line(out, "RMS spot radius at best", a.focus.rmsSpotRadius);
    out += "\nSurfaces\n    #        z (mm)    radius (mm)        N   diameter (mm)\n";
    for (std::size_t i = 0; i < a.lens.surfaces.size(); ++i) {
        const Surface& s = a.lens.surfaces[i];
        std::snprintf(b, sizeof b, "  %3zu  %12.4f  %13.4f  %7.4f  %14.4f%s\n", i + 1, s.z, s.radius, s.indexAfter,
                      2 * s.apertureRadius, s.isStop ? "  stop" : "");
        out += b;
    }
    return out;
}

}  // namespace lenslab
