// `lenslab report`: builds the report site (lens data, diagrams, renders, plots) into a folder.
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>

#include "ArgParser.h"
#include "BuildReport.h"
#include "Commands.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

std::vector<std::string> commaList(const std::string& text) {
    std::vector<std::string> items;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

}  // namespace

int runReportCommand(const std::vector<std::string>& args) {
    ArgParser p("report", "-o DIR [--spp N] [--width N] [--lenses ID,FILE,...] [--quick] [--fstop N] [--focus MM|inf]",
                "Writes the report web page into DIR: index.html, style.css and assets/, relative links only,\n"
                "readable from the file system or served. Per lens: the first-order table, diagrams (exact,\n"
                "thick, overlay), thick-lens error, relative illumination and distortion plots, the lens designer's\n"
                "analysis (spot diagrams, MTF, ray fans, field curvature, distortion, chromatic focal shift); per scene with\n"
                "a realistic camera: renders through the common-scale lenses, accurate against approximate.\n"
                "Items whose inputs did not change since the last build into DIR are reused (DIR/manifest.json).");
    p.option("-o", "DIR", "output folder (created if needed)");
    const ReportOptions defaults;
    p.option("--spp", "N", "samples per pixel of the renders (default " + std::to_string(defaults.spp) + ")");
    p.option("--width", "N", "render width in pixels (default " + std::to_string(defaults.width) +
                                 "; height from the scene's aspect)");
    p.option("--lenses", "LIST", "comma-separated lens ids (bundled) or lens table files (default: every bundled lens)");
    p.option("--extra-lenses", "LIST", "comma-separated lens table files added to those (uploaded lenses)");
    p.option("--fstop", "N", "f-number of the tables and diagrams (default: each lens's widest)");
    p.option("--focus", "MM", "focus distance of the tables and diagrams, mm from the front vertex, or inf (default " +
                                  formatNumber(defaults.focusDistance) + ")");
    p.option("--render-fstop", "N", "f-number of the renders, raised to a slower lens's widest (default " +
                                        formatNumber(defaults.renderFstop) + ")");
    p.option("--threads", "N", "render threads (default: all cores)");
    p.option("--lens-dir", "DIR", "bundled lens tables (default: the source tree's lenses/)");
    p.option("--scene-dir", "DIR", "bundled scenes (default: the source tree's scenes/)");
    p.flag("--quick", "tiny renders and few samples: a whole report in seconds, for tests");
    p.flag("--quiet", "no progress lines");
    if (!p.parse(args)) {
        std::cout << p.help();
        return 0;
    }
    if (!p.has("-o")) throw UsageError("report: -o DIR is required");
    ReportOptions o = defaults;
    o.outputDir = p.get("-o");
    o.lensDir = p.get("--lens-dir");
    o.sceneDir = p.get("--scene-dir");
    o.lenses = commaList(p.get("--lenses"));
    o.extraLenses = commaList(p.get("--extra-lenses"));
    o.fstop = p.number("--fstop");
    if (p.has("--focus")) {
        o.focusDistance = parseDistance(p.get("--focus"), "--focus");
        o.focusGiven = true;
    }
    o.renderFstop = p.number("--render-fstop").value_or(o.renderFstop);
    o.spp = static_cast<int>(p.integer("--spp").value_or(o.spp));
    o.width = static_cast<int>(p.integer("--width").value_or(o.width));
    o.threads = static_cast<int>(p.integer("--threads").value_or(0));
    o.quick = p.has("--quick");
    if (o.spp < 1 || o.width < 8 || o.threads < 0) throw UsageError("report: --spp must be >= 1, --width >= 8, --threads >= 0");

    const bool quiet = p.has("--quiet");
    const ReportSummary s = buildReport(o, [&](const ReportProgress& r) {
        if (!quiet) std::fprintf(stderr, "[%d/%d] %s%s\n", r.done, r.total, r.item.c_str(), r.reused ? " (reused)" : "");
    });
    std::printf("report: %d lenses, %d scenes; %d items: %d built, %d reused; %d renders; %.1f s\n", s.lenses, s.scenes,
                s.items, s.built, s.reused, s.renders, s.seconds);
    for (const std::string& problem : s.problems) std::printf("problem: %s\n", problem.c_str());
    std::printf("wrote %s\n", s.indexPath.string().c_str());
    return s.problems.empty() ? 0 : 1;
}

}  // namespace lenslab
