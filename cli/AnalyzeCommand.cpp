#include <filesystem>
#include <fstream>
#include <iostream>

#include "AnalysisInputsText.h"
#include "AnalysisJson.h"
#include "AnalysisPlots.h"
#include "AnalysisTables.h"
#include "ArgParser.h"
#include "Commands.h"
#include "GhostFormats.h"
#include "GhostPlot.h"
#include "analysis/GhostAnalysis.h"
#include "analysis/LensDesignAnalysis.h"
#include "LensFlags.h"

namespace lenslab {

namespace {

DesignAnalysisInputs analysisFlags(const ArgParser& p) {
    DesignAnalysisInputs in;
    in.lens = lensFlags(p);
    in.wavelengthsSource = "--wavelengths";
    in.fieldsSource = "--fields";
    in.maxFrequencySource = "--max-frequency";
    try {
        if (p.has("--wavelengths")) in.wavelengths = parseWavelengthList(p.get("--wavelengths"), "--wavelengths");
        if (p.has("--fields")) {
            const FieldList fields = parseFieldList(p.get("--fields"), "--fields");
            in.fields = fields.values;
            in.fieldsInDegrees = fields.degrees;
        }
        if (p.has("--image-plane")) in.imagePlane = parseImagePlaneInput(p.get("--image-plane"), "--image-plane");
        if (p.has("--reference")) in.reference = parseSpotReferenceInput(p.get("--reference"), "--reference");
    } catch (const InputListError& e) {
        throw UsageError(std::string("analyze: ") + e.what());
    }
    if (const auto max = p.number("--max-frequency")) in.maxFrequency = *max;
    return in;
}

void printSummary(const LensDesignAnalysis& a) {
    std::cout << a.lens.lens.name << ": " << analysisSettingsText(a) << "\n" << analysisTablesText(a);
}

// Files by name and text, each ending in a newline.
using NamedTexts = std::vector<std::pair<std::string, std::string>>;

void writeFiles(const std::string& folder, const NamedTexts& files) {
    std::filesystem::create_directories(folder);
    for (const auto& [name, text] : files) {
        std::ofstream out(std::filesystem::path(folder) / name, std::ios::binary);
        out << text << "\n";
        if (!out) throw std::runtime_error("cannot write " + (std::filesystem::path(folder) / name).string());
    }
}

void writeOutputFolder(const LensDesignAnalysis& a, const std::string& folder) {
    NamedTexts files{{"analysis.json", designAnalysisJson(a).dump(1)}};
    for (const NamedSvg& plot : designAnalysisPlots(a)) files.push_back({plot.name + ".svg", plot.svg});
    writeFiles(folder, files);
}

// --ghosts: the ghost-focus analysis at the lens settings, at the d line.
int runGhostAnalysis(const ArgParser& p) {
    LensSettings settings = lensFlags(p);
    settings.wavelength = Setting{kWavelengthD, "the d line"};
    const LensAnalysis lens = analyzeLens(loadLensSystem(p.arg(0)), settings);
    const GhostAnalysis ghosts = analyzeGhosts(lens);
    if (p.has("--json")) std::cout << ghostAnalysisJson(ghosts).dump(2) << "\n";
    else std::cout << ghostAnalysisText(ghosts, lens);
    if (p.has("-o")) writeFiles(p.get("-o"), {{"ghosts.json", ghostAnalysisJson(ghosts).dump(1)}, {"ghosts.svg", ghostPlotSvg(ghosts, "ghosts")}});
    return 0;
}

}  // namespace

int runAnalyzeCommand(const std::vector<std::string>& args) {
    ArgParser p("analyze",
                "LENS [--fstop N] [--focus MM|inf] [--wavelengths F,d,C|NM,...] [--fields 0,0.7,1|DEGdeg,...] [--image-plane P] [--reference R] [--ghosts] [--json] [-o DIR]",
                "The lens designer's analysis: spot diagrams, ray fans, geometric and diffraction MTF per field;\n"
                "field curvature, distortion, relative illumination and chromatic focal shift. Each number's\n"
                "definition is in docs/analysis.md and in the JSON. Fields are fractions of the largest field (the\n"
                "lens's own: see 'lenslab lens'), or degrees with 'deg'. -o writes analysis.json and SVG plots into DIR.\n"
                "--ghosts: the ghost analysis instead (docs/flare.md).");
    p.positional("LENS", "lens table (.dat) or Zemax file (.zmx)");
    declareLensFlags(p);
    p.option("--wavelengths", "LIST", "F, d, C or nm, comma-separated (default F,d,C; at most 16)");
    p.option("--fields", "LIST", "fractions of the largest field, or degrees with 'deg' (default 0,0.7,1; at most 16)");
    p.option("--max-frequency", "LPMM", "the MTF's largest frequency (default 200, or the diffraction cutoff 1/(lambda N) when lower)");
    p.option("--image-plane", "PLANE", "paraxial, film (default: where the camera focuses) or best (least RMS over the fields)");
    p.option("--reference", "POINT", "spot radii about the centroid (default) or the chief ray");
    p.flag("--json", "print the analysis as one JSON object");
    p.option("-o", "DIR", "write analysis.json and the plots (SVG) into DIR");
    p.flag("--ghosts", "the ghost-focus analysis instead: every two-reflection path's paraxial image, its blur on the film and\n"
                       "its intensity beside the direct image, brightest first (-o: ghosts.json and ghosts.svg)");
    if (!p.parse(args)) {
        std::cout << p.help();
        return 0;
    }
    if (p.has("--ghosts")) return runGhostAnalysis(p);
    const LensDesignAnalysis a = analyzeLensDesign(loadLensSystem(p.arg(0)), analysisFlags(p));
    if (p.has("--json")) std::cout << designAnalysisJson(a).dump(2) << "\n";
    else printSummary(a);
    if (p.has("-o")) writeOutputFolder(a, p.get("-o"));
    return 0;
}

}  // namespace lenslab
