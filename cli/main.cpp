// lenslab: realistic camera lenses, from lens tables to diagrams, renders and a web service.
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "ArgParser.h"
#include "Commands.h"
#include "GlassCatalogFlags.h"
#include "prescription/LensTable.h"
#include "prescription/OpticsError.h"

namespace {

struct Subcommand {
    const char* name;
    const char* summary;
    int (*run)(const std::vector<std::string>&);
};

const Subcommand kSubcommands[] = {
    {"lens", "first-order data of a lens table (EFL, F, F', P, P', pupils, f-number, focus)", lenslab::runLensCommand},
    {"analyze", "spot diagrams, ray fans, MTF, field curvature, distortion, focal shift (SVG and JSON)", lenslab::runAnalyzeCommand},
    {"optimise", "damped least squares on a merit function, the optimised lens written as .zmx, .seq or .dat", lenslab::runOptimiseCommand},
    {"tolerance", "sensitivity and Monte Carlo tolerancing with compensators; the as-built lenses", lenslab::runToleranceCommand},
    {"diagram", "the lens cross-section with ray fans as a PNG (offscreen OpenGL)", lenslab::runDiagramCommand},
    {"render", "render a scene (pbrt-v3 subset) with a perspective or realistic lens camera", lenslab::runRenderCommand},
    {"report", "the report web page: lens data, diagrams, renders and plots in a folder", lenslab::runReportCommand},
    {"serve", "the HTTP service and web page (REST API: docs/api.md)", lenslab::runServeCommand},
};

void printUsage(std::ostream& out) {
    out << "usage: lenslab COMMAND [ARGS]   (lenslab COMMAND --help for details)\n\ncommands:\n";
    for (const auto& c : kSubcommands) out << "  " << c.name << std::string(10 - std::strlen(c.name), ' ') << c.summary << "\n";
    out << "\nevery command: --glass-catalog FILE.agf (repeatable) adds a Zemax glass catalog, searched before the\n"
           "bundled one; so does every .agf in the folder LENSLAB_GLASS_CATALOGS names\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
        printUsage(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? 2 : 0;
    }
    const std::vector<std::string> args(argv + 2, argv + argc);
    for (const auto& c : kSubcommands) {
        if (c.name != std::string(argv[1])) continue;
        try {
            return c.run(lenslab::loadGlassCatalogs(args));
        } catch (const lenslab::UsageError& e) {
            std::cerr << "lenslab " << e.what() << "\n";
            return 2;
        } catch (const lenslab::LensTableError& e) {
            std::cerr << "lenslab: " << e.what() << "\n";
            return 1;
        } catch (const std::exception& e) {
            std::cerr << "lenslab " << c.name << ": " << e.what() << "\n";
            return 1;
        }
    }
    std::cerr << "lenslab: unknown command '" << argv[1] << "'\n";
    printUsage(std::cerr);
    return 2;
}
