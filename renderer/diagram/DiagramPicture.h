#pragma once
// Everything the diagram shows, laid out in picture pixels: the shapes for OpenGL and the text
// labels drawn after read-back. No GL here, so layout and ray geometry can be tested directly.
#include <string>
#include <vector>

#include "settings/LensAnalysis.h"
#include "LensDiagram.h"
#include "RayFans.h"
#include "TextRaster.h"
#include "ViewFit.h"

namespace lenslab {

struct DiagramPicture {
    int width = 0, height = 0;
    DrawList shapes;
    std::vector<TextLabel> labels;
    ViewTransform view;       // lens mm to picture pixels
    PictureBox content;       // the lens and rays live here; labels and caption around it
    std::vector<FanRay> rays;  // as traced (lens mm), before clipping to `content`
    double fieldDegrees = 0;  // the off-axis fan's field (object space); 0: the axial fan only
    double fieldHeight = 0;   // mm below the axis where that field's chief ray meets the film
};

// Lays out the diagram for an analysed lens; `options` are already validated.
DiagramPicture composeDiagram(const LensAnalysis& analysis, const std::string& lensName, const DiagramOptions& options);

}  // namespace lenslab
