#pragma once
// The lens designer's plots of an analysis, as SVG (svgPlot): spot diagrams, MTF, ray fans per
// field; field curvature, distortion, relative illumination and chromatic focal shift.
#include <string>
#include <vector>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

struct NamedSvg {
    std::string name;  // a file stem: "spot-field-1", "mtf-field-1", "field-curvature", ...
    std::string svg;
};

std::vector<NamedSvg> designAnalysisPlots(const LensDesignAnalysis& analysis);

// The settings every analysis view names beside its numbers: f-number, focus, image plane,
// reference point, primary wavelength and the largest field with its source.
std::string analysisSettingsText(const LensDesignAnalysis& analysis);

}  // namespace lenslab
