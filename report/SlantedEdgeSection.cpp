#include "SlantedEdgeSection.h"

#include <sstream>

#include "MarkupText.h"
#include "SiteFiles.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

struct EdgeChoice {
    int chartStep;
    MtfDirection direction;
};

// The section's lenses, both without dispersion (the render's RGB and the analysis's F, d, C see
// one index per glass), each on the axis and near 0.7 of the 24 x 36 mm film corner's field.
struct SectionLens {
    const char* id;
    double fstop;
    std::vector<EdgeChoice> edges;
};
const std::vector<SectionLens>& sectionLenses() {
    static const std::vector<SectionLens> lenses = {
        // The corner of the film is 23.2 degrees off the axis: 16 is 0.69 of it.
        {"dgauss.50mm", 4, {{0, MtfDirection::Tangential}, {8, MtfDirection::Tangential}, {8, MtfDirection::Sagittal}}},
        // The corner is 44.1 degrees off the axis: 30 is 0.68 of it.
        {"wide.22mm", 4, {{0, MtfDirection::Tangential}, {15, MtfDirection::Tangential}, {15, MtfDirection::Sagittal}}},
    };
    return lenses;
}

std::string edgeName(const SectionLens& lens, const EdgeChoice& e) {
    return std::string(lens.id) + "-" + std::to_string(e.chartStep) + "-" + edgeDirectionName(e.direction);
}

EdgePlot edgeItem(ItemRunner& runner, const SceneSource& chart, const LensEntry& lens, const SectionLens& choice,
                  const EdgeChoice& edge, const EdgeCase& settings) {
    EdgePlot out;
    out.lensId = lens.facts.id;
    out.direction = edgeDirectionName(edge.direction);
    const std::string name = edgeName(choice, edge);
    const std::string file = "assets/slanted-edge/" + name + ".svg";
    InputsHash h = itemInputs("slanted-edge");
    for (const std::string& f : chart.files) h.addFile(f);
    h.addFile(lens.facts.path).add(choice.fstop).add(double(edge.chartStep)).add(out.direction);
    h.add(double(settings.spp)).add(double(settings.cropPixels));
    const ManifestItem* item = runner.run("slanted-edge/" + name, "slanted edge " + name, h.hex(), [&] {
        runner.countRender();
        EdgeCase c = settings;
        c.lensPath = lens.facts.path;
        c.fstop = choice.fstop;
        c.chartStep = edge.chartStep;
        c.direction = edge.direction;
        const EdgeComparison e = compareSlantedEdge(c);
        writeSiteFile(runner.site(), file, svgPlot(slantedEdgePlot(e, lens.facts.id, "edge-" + name)));
        ManifestItem m;
        m.files = {file};
        m.data = {{"field_deg", e.fieldDegrees}, {"fstop", e.fstop}, {"max_difference", e.maxDifference}};
        return m;
    });
    if (!item) {
        out.problem = "the comparison failed (see the problems list)";
        return out;
    }
    out.plot = file;
    out.fieldDegrees = item->data.at("field_deg").get<double>();
    out.fstop = item->data.at("fstop").get<double>();
    out.maxDifference = item->data.at("max_difference").get<double>();
    return out;
}

}  // namespace

const char* edgeDirectionName(MtfDirection d) { return d == MtfDirection::Sagittal ? "sagittal" : "tangential"; }

Plot slantedEdgePlot(const EdgeComparison& e, const std::string& lensId, const std::string& id) {
    Plot p;
    p.id = id;
    p.title = lensId + ", " + formatFixed(e.fieldDegrees, 1) + "\u00b0 " + edgeDirectionName(e.direction) + ", f/" + formatFNumber(e.fstop);
    p.x.label = "spatial frequency (lp/mm); pixel Nyquist " + formatNumber(0.5 / e.pixelMm);
    p.y.label = "modulation";
    p.x.min = 0;
    p.x.max = 0.5 / e.pixelMm;
    p.y.min = 0;
    p.y.max = 1;
    p.series.push_back({"render: e-SFR", e.frequencies, e.measured, SeriesStyle::Markers});
    p.series.push_back({"analysis \u00d7 pixel", e.frequencies, e.predicted});
    p.series.push_back({"analysis (geometric, film)", e.frequencies, e.lens, SeriesStyle::Line, LineDash::Dashed});
    p.series.push_back({"pixel (square)", e.frequencies, e.pixel, SeriesStyle::Line, LineDash::Dashed});
    const double half = 0.25 / e.pixelMm;
    p.series.push_back({"half Nyquist", {half, half}, {0, 1}, SeriesStyle::Line, LineDash::Dashed});
    return p;
}

int slantedEdgeItemCount(const std::vector<std::string>& lensIds) {
    int count = 0;
    for (const SectionLens& l : sectionLenses())
        for (const std::string& id : lensIds)
            if (id == l.id) count += int(l.edges.size());
    return count;
}

SlantedEdges buildSlantedEdges(ItemRunner& runner, const SceneSource& chart, const std::vector<LensEntry>& lenses,
                               const ReportOptions& o) {
    SlantedEdges out;
    EdgeCase settings;
    settings.scenePath = chart.path;
    // Fewer samples, or a smaller crop cutting the line spread of wide.22mm's 30 degrees, part the curves
    // by more than the 0.05 the section states.
    settings.spp = o.quick ? 64 : 256;
    settings.cropPixels = 64;
    settings.threads = o.threads;
    out.spp = settings.spp;
    out.cropPixels = settings.cropPixels;
    for (const SectionLens& choice : sectionLenses())
        for (const LensEntry& lens : lenses) {
            if (lens.facts.id != choice.id) continue;
            for (const EdgeChoice& edge : choice.edges) {
                if (lens.facts.error.empty()) out.plots.push_back(edgeItem(runner, chart, lens, choice, edge, settings));
                else runner.skip("slanted edge " + edgeName(choice, edge));
            }
        }
    return out;
}

std::string slantedEdgeSectionHtml(const SlantedEdges& edges) {
    if (edges.plots.empty()) return "";
    std::ostringstream out;
    out << "<section id=\"render-against-analysis\">\n<h2>The render against the analysis</h2>\n"
           "<p>The slanted-edge chart (<code>scenes/slanted-edge.pbrt</code>: glowing squares turned 5\u00b0, 5 m away, "
           "where the camera focuses) rendered through the lens on a 24 \u00d7 36 mm (portrait) film of 4 \u00b5m pixels, a crop of "
        << edges.cropPixels << " \u00d7 " << edges.cropPixels << " pixels around one edge at " << edges.spp
        << " samples per pixel, measured by the e-SFR method of ISO 12233 (the edge spread binned four to a pixel "
           "along the edge's normal, its derivative under a Hamming window, the Fourier transform, divided by the "
           "finite difference's own transfer). Against it the analysis's geometric MTF (the ray tracer has no "
           "diffraction) on the film plane at the edge's field, sagittal for an edge along the field's radius and "
           "tangential for one across it, times the square pixel's MTF (the scene's box filter of one pixel). They "
           "agree within 0.05 up to half the pixel Nyquist (tests/report/test_slanted_edge.cpp checks it).</p>\n";
    out << "<div class=\"plots\">\n";
    for (const EdgePlot& p : edges.plots) {
        if (!p.problem.empty()) {
            out << "<p class=\"problem\">" << escapeMarkup(p.lensId + " (" + p.direction + "): " + p.problem) << "</p>\n";
            continue;
        }
        const std::string caption = p.lensId + " at f/" + formatFNumber(p.fstop) + ", " + formatFixed(p.fieldDegrees, 1) + "\u00b0 " +
                                    p.direction + ": the largest |e-SFR \u2212 analysis \u00d7 pixel| up to half Nyquist is " +
                                    formatFixed(p.maxDifference, 3) + ".";
        const std::string href = escapeMarkup(p.plot);
        out << "<figure>\n<a href=\"" << href << "\"><img src=\"" << href << "\" alt=\"" << escapeMarkup(caption)
            << "\" loading=\"lazy\"></a>\n<figcaption>" << escapeMarkup(caption) << "</figcaption>\n</figure>\n";
    }
    out << "</div>\n</section>\n";
    return out.str();
}

}  // namespace lenslab
