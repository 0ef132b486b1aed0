#pragma once
// How a lens table is set to work: its aperture (an f-number, or the stop's own diameter as pbrt-v3
// scenes give it) and its focus (a plane of focus, measured from the front vertex or, as pbrt-v3
// measures it, from the film; or the film placed directly behind the rear vertex). Every front end
// (command-line flags, JSON fields, scene parameters of each generation) fills one of these and
// names where each value came from; analyzeLens (LensAnalysis.h) is the one place that checks them
// against the lens, and its errors name that source.
#include <optional>
#include <string>

#include "prescription/Wavelength.h"  // the range any front end accepts

namespace lenslab {

// A setting and where it came from, for messages: "--fstop", "field fstop",
// "scene.pbrt:5: Camera \"realistic\": fstop".
struct Setting {
    double value = 0;
    std::string source;
};

// The film an iterated focus is solved for when the focus is measured from the film.
enum class FocusModel { Exact, Thick };

struct LensSettings {
    std::optional<Setting> fstop;          // f-number; none (and no stop diameter): the widest
    std::optional<Setting> stopDiameter;   // mm, the stop's opening
    std::optional<Setting> focusDistance;  // mm to the plane of focus; none (and no film distance): infinity
    bool focusFromFilm = false;            // focusDistance measured from the film (pbrt-v3), not the front vertex
    FocusModel focusModel = FocusModel::Exact;
    std::optional<Setting> filmDistance;   // mm, rear vertex to film: placed, not focused
    std::optional<Setting> wavelength;     // nm; none: the prescription's primary wavelength
};

}  // namespace lenslab
