#include "GhostFormats.h"

#include <cmath>
#include <cstdio>

#include "FiniteOrNull.h"
#include "prescription/NumberText.h"

namespace lenslab {

std::string ghostAnalysisText(const GhostAnalysis& g, const LensAnalysis& a) {
    std::string out = "Ghosts of " + a.lens.name + " at f/" + formatFNumber(a.fstop) + ", focus " +
                      (a.focus.infinity ? std::string("infinity") : formatNumber(a.focus.objectZ - a.lens.frontZ()) + " mm") +
                      ", " + formatFixed(g.wavelength, 2) + " nm: " + std::to_string(g.reflectingSurfaces) +
                      " reflecting surfaces, " + std::to_string(g.ghosts.size()) + " two-reflection paths, brightest first\n";
    out += "paraxial, on axis; intensity: peak irradiance against the direct image of a source " +
           formatNumber(kGhostSourceDiameterDegrees) + " deg across (the sun); focused: blur under " +
           formatNumber(kFocusedGhostDiameterMm) + " mm\n";
    out += "rank  surfaces   R1 %    R2 %   focus from film (mm)  blur (mm)  field scale    energy   intensity\n";
    char b[200];
    int rank = 0;
    for (const GhostImage& x : g.ghosts) {
        std::snprintf(b, sizeof b, "%4d  %3d - %-3d %6.3f  %6.3f  %20.3f  %9.3f  %11.4f  %8.2e  %10.2e%s\n", ++rank,
                      x.path.first + 1, x.path.second + 1, 100 * x.reflectanceFirst, 100 * x.reflectanceSecond,
                      x.focusFromFilm, x.blurDiameter, x.fieldScale, x.energy, x.relativeIntensity,
                      x.focused ? "  focused" : "");
        out += b;
    }
    return out;
}

nlohmann::json ghostAnalysisJson(const GhostAnalysis& g) {
    nlohmann::json ghosts = nlohmann::json::array();
    for (const GhostImage& x : g.ghosts)
        ghosts.push_back({{"surfaces", {x.path.first + 1, x.path.second + 1}},
                          {"reflectance", {x.reflectanceFirst, x.reflectanceSecond}},
                          {"focus_z", finiteOrNull(x.focusZ)},
                          {"focus_from_film_mm", finiteOrNull(x.focusFromFilm)},
                          {"blur_diameter_mm", x.blurDiameter},
                          {"field_scale", x.fieldScale},
                          {"energy", x.energy},
                          {"relative_intensity", x.relativeIntensity},
                          {"focused", x.focused}});
    return {{"wavelength_nm", g.wavelength},
            {"film_z", g.filmZ},
            {"reflecting_surfaces", g.reflectingSurfaces},
            {"source_diameter_deg", kGhostSourceDiameterDegrees},
            {"focused_below_mm", kFocusedGhostDiameterMm},
            {"ghosts", ghosts}};
}

}  // namespace lenslab
