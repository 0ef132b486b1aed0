#pragma once
// The lens designer's plots of an analysis, as SVG (svgPlot): spot diagrams, MTF, ray fans per
// field; field curvature, distortion, relative illumination and chromatic focal shift. The report,
// `lenslab analyze -o` and the web page (through the API) show these same plots.
#include <string>
#include <vector>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

struct NamedSvg {
    std::string name;     // a file stem: "spot-field-1", "mtf-field-1", "field-curvature", ...
    std::string caption;  // what the plot shows, in a sentence
    std::string svg;
};

// The plots, per field (spot, MTF, fans) and then against field and wavelength. `curves`: the
// curves against field too (an analysis with only their two end points, as the editor's preview
// asks for, draws none of them).
std::vector<NamedSvg> designAnalysisPlots(const LensDesignAnalysis& analysis, bool curves = true);

// One colour per wavelength in every plot (spots, fans, field curvature): F blue, d green, C
// vermilion (Okabe & Ito's colour-blind-safe hues), other wavelengths between them.
std::string wavelengthColour(double nanometres);

}  // namespace lenslab
