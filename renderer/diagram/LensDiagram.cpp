#include "LensDiagram.h"

#include <cmath>

#include "DiagramPicture.h"
#include "DiagramStyle.h"
#include "settings/LensAnalysis.h"
#include "prescription/NumberText.h"
#include "PngCodec.h"
#include "CanvasLease.h"

namespace lenslab {

namespace {

constexpr int kMinWidth = 320, kMinHeight = 200, kMaxSide = 8192;
constexpr int kMaxRays = 201;

void validate(const DiagramOptions& o) {
    if (o.width < kMinWidth || o.height < kMinHeight || o.width > kMaxSide || o.height > kMaxSide)
        throw DiagramError("diagram size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                           " is outside " + std::to_string(kMinWidth) + "x" + std::to_string(kMinHeight) + " to " +
                           std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide) + " pixels");
    if (o.rays < 1 || o.rays > kMaxRays)
        throw DiagramError("rays per fan must be 1 to " + std::to_string(kMaxRays) + ", got " + std::to_string(o.rays));
    if (o.fieldHeight && !(std::isfinite(*o.fieldHeight) && *o.fieldHeight >= 0))
        throw DiagramError("field height must be a non-negative number of mm on the film, got " + formatNumber(*o.fieldHeight));
}

}  // namespace

DiagramMode parseDiagramMode(const std::string& name) {
    if (name == "exact") return DiagramMode::Exact;
    if (name == "thick") return DiagramMode::Thick;
    if (name == "overlay") return DiagramMode::Overlay;
    throw DiagramError("diagram mode must be exact, thick or overlay, got '" + name + "'");
}

DiagramBackendKind parseDiagramBackend(const std::string& name) {
    if (name == "osmesa") return DiagramBackendKind::OSMesa;
    if (name == "egl") return DiagramBackendKind::EGL;
    if (name == "auto") return DiagramBackendKind::Auto;
    throw DiagramError("diagram backend must be osmesa, egl or auto, got '" + name + "'");
}

std::vector<std::uint8_t> drawLensDiagramPng(const LensSystem& lens, const DiagramOptions& options) {
    validate(options);
    const LensAnalysis analysis = analyzeLens(lens, options.lens);
    const DiagramPicture picture = composeDiagram(analysis, lensFileStem(lens.name), options);
    std::vector<std::uint8_t> pixels = CanvasLease(options.backend)
                                           .canvas()
                                           .rasterise(picture.shapes, picture.width, picture.height, diagram_style::kBackground);
    drawTextLabels(pixels, picture.width, picture.height, picture.labels, diagram_style::kBackground);
    return encodePngRgba8(picture.width, picture.height, pixels.data());
}

}  // namespace lenslab
