#pragma once
// Everything the report page shows, gathered (or read from the cache) before the HTML is written.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "LensFacts.h"
#include "SceneFiles.h"

namespace lenslab {

struct DiagramImage {
    std::string mode;   // "exact", "thick", "overlay"
    std::string image;  // path relative to the site folder
    int width = 0, height = 0;
};

struct RenderRecord {
    std::string image;  // relative to the site folder
    std::string mode;   // "exact" | "thick"
    int width = 0, height = 0, spp = 0;
    double fstop = 0;
    double exposure = 1;  // PNG scale of the linear image
    double setupSeconds = 0, renderSeconds = 0;
    std::uint64_t cameraRays = 0, blockedCameraRays = 0, raysTraced = 0;
};

// A dispersive lens through the lateral colour chart: the spectral render (colour fringes) beside
// the RGB render at the lens's own wavelength (none).
struct ColourFringes {
    double fstop = 0;  // the chart's f-number, asked for (the renders' when they are made)
    RenderRecord spectral, rgb;
    std::string problem;  // why they are missing
};

// The lens designer's analysis at the report's settings (lenslab analyze's defaults: F, d, C at
// fields 0, 0.7, 1): its plots as SVG files and the data as JSON.
struct DesignPlots {
    std::vector<std::string> plots;     // SVG files relative to the site folder, in designAnalysisPlots' order
    std::vector<std::string> captions;  // each plot's
    std::string jsonFile;
    double fstop = 0;
    std::string focus;                     // "infinity" or the distance, "2000 mm"
    std::string settingsHtml, tablesHtml;  // the settings and the numbers, each marked with its place in the JSON
    std::string problem;                   // why they are missing
    nlohmann::json ghosts;                 // the ghost analysis (ghostAnalysisJson), its plot the last of `plots`
};

struct LensEntry {
    LensFacts facts;
    std::string name;      // its heading: the id, or the name it was given (ReportOptions::lensNames)
    std::string fileName;  // the file `lenslab lens` reads: the name given, else the file's own
    std::vector<DiagramImage> diagrams;
    DesignPlots design;
    std::string jsonFile;  // the table's JSON, as `lenslab lens --json` prints it
    std::string problem;   // a diagram that could not be drawn
    std::optional<ColourFringes> colourFringes;  // dispersive lenses, when the chart scene exists
};


// An edge of the slanted-edge chart through a lens: the crop's e-SFR against the analysis's MTF
// times the pixel's (SlantedEdgeSection.h).
struct EdgePlot {
    std::string lensId, direction;  // "tangential" | "sagittal"
    std::string plot;               // SVG file relative to the site folder
    double fieldDegrees = 0, fstop = 0;
    double maxDifference = 0;       // |e-SFR - prediction| up to half the pixel Nyquist
    std::string problem;            // why the plot is missing
};

struct SlantedEdges {
    std::vector<EdgePlot> plots;
    int spp = 0, cropPixels = 0;
};

struct RenderPair {
    std::string lensId;
    RenderRecord accurate, approximate;
    std::string differenceImage;  // |accurate - approximate| of the 8-bit sRGB images, times differenceGain
    double differenceGain = 0;
    double rmsDifference = 0;     // in 8-bit sRGB levels
    std::string problem;          // why the pair is missing
};

struct ReportScene {
    SceneSource scene;
    std::vector<RenderPair> pairs;  // empty for a scene without a realistic camera
};

// Error against a converged render as the sample count grows: the cost of accuracy.
struct SpeedPoint {
    std::string mode;
    int spp = 0;
    double seconds = 0;    // setup + render
    double rmsError = 0;   // against the accurate render at the report's sample count, 8-bit sRGB levels
};

struct SpeedStudy {
    std::string sceneId, lensId;
    int referenceSpp = 0;
    std::vector<SpeedPoint> points;
};

// One scene through one lens at rising ISO, a 100% crop of a full-frame sensor with Nikon D850
// pixels (docs/sensor.md): the same metered brightness, the noise of less and less light.
struct SensorRung {
    double iso = 0;
    RenderRecord render;
    double noise = 0;  // rms of pixel minus its 5 x 5 neighbourhood's mean, over the mean (8-bit sRGB green)
};

struct SensorLadder {
    std::string sceneId, lensId;
    std::vector<SensorRung> rungs;
    std::string problem;  // why rungs are missing
};

struct ReportContent {
    std::string version, generatedAt;
    std::vector<std::string> parameters;  // "name: value" lines shown in the header
    std::vector<LensEntry> lenses;
    std::vector<ReportScene> scenes;
    SpeedStudy speed;
    SlantedEdges slantedEdges;
    SensorLadder sensorLadder;
    std::vector<std::string> problems;
};

}  // namespace lenslab
