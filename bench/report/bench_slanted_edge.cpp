// The render against the analysis at every field of the slanted-edge chart (report/SlantedEdgeComparison.h):
// for each lens, each edge from the axis out to the film's edge, tangential and sagittal, the largest
// |e-SFR - analysis x pixel| up to half the pixel Nyquist as a Markdown table row, and the comparison
// plot as OUTDIR/<lens>-<field>-<direction>.svg.
//
//   bench_slanted_edge OUTDIR [--spp N] [--crop N] [LENS FSTOP]...   (default: dgauss.50mm 4 wide.22mm 4)
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ProcessCpuTime.h"
#include "SlantedEdgeSection.h"
#include "prescription/NumberText.h"

namespace fs = std::filesystem;
using namespace lenslab;

namespace {

struct LensAt {
    std::string path;
    double fstop;
};

// The lens's MTF at half Nyquist: how much the lens itself weighs in the comparison.
double lensAtHalfNyquist(const EdgeComparison& e) {
    double value = 1;
    for (std::size_t k = 0; k < e.frequencies.size() && e.frequencies[k] * e.pixelMm <= 0.25 + 1e-12; ++k) value = e.lens[k];
    return value;
}

// Every edge of the chart through one lens, from the axis out until an edge's image leaves the film.
void sweep(const LensAt& lens, const EdgeCase& base, const fs::path& out) {
    const std::string id = fs::path(lens.path).stem().string();
    for (int step = 0; step <= kChartSteps; ++step)
        for (MtfDirection direction : {MtfDirection::Tangential, MtfDirection::Sagittal}) {
            if (step == 0 && direction == MtfDirection::Sagittal) continue;
            EdgeCase c = base;
            c.lensPath = lens.path;
            c.fstop = lens.fstop;
            c.chartStep = step;
            c.direction = direction;
            const double cpu = bench::processCpuSeconds();
            try {
                const EdgeComparison e = compareSlantedEdge(c);
                const std::string name = id + "-" + std::to_string(step * int(kChartStepDegrees)) + "-" + edgeDirectionName(direction);
                std::ofstream(out / (name + ".svg")) << svgPlot(slantedEdgePlot(e, id, name));
                std::printf("| %s | f/%s | %.2f | %s | %.3f | %.3f | %.1f |\n", id.c_str(), formatFNumber(e.fstop).c_str(), e.fieldDegrees,
                            edgeDirectionName(direction), e.maxDifference, lensAtHalfNyquist(e), bench::processCpuSeconds() - cpu);
            } catch (const std::out_of_range& offFilm) {
                std::printf("\n%s: %s\n\n", id.c_str(), offFilm.what());
                return;
            } catch (const std::exception& error) {
                std::printf("| %s | f/%s | %d | %s | failed: %s | | |\n", id.c_str(), formatFNumber(lens.fstop).c_str(),
                            step * int(kChartStepDegrees), edgeDirectionName(direction), error.what());
            }
            std::fflush(stdout);
        }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUTDIR [--spp N] [--crop N] [LENS FSTOP]...\n", argv[0]);
        return 2;
    }
    const fs::path out = argv[1];
    fs::create_directories(out);
    EdgeCase base;
    base.scenePath = std::string(LENSLAB_SOURCE_DIR) + "/scenes/slanted-edge.pbrt";
    base.spp = 64;
    std::vector<LensAt> lenses;
    try {
        for (int k = 2; k < argc; ++k) {
            const std::string a = argv[k];
            if (k + 1 >= argc) throw std::invalid_argument(a + " wants a value after it");
            if (a == "--spp") base.spp = std::stoi(argv[++k]);
            else if (a == "--crop") base.cropPixels = std::stoi(argv[++k]);
            else lenses.push_back({a, std::stod(argv[++k])});
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_slanted_edge: %s\n", error.what());
        return 2;
    }
    if (lenses.empty())
        for (const char* id : {"dgauss.50mm", "wide.22mm"}) lenses.push_back({std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + id + ".dat", 4});
    std::printf("%d x %d pixel crops, %d spp\n\n| lens | stop | field (deg) | edge | max difference | lens MTF at half Nyquist | CPU s |\n"
                "|---|---|---|---|---|---|---|\n",
                base.cropPixels, base.cropPixels, base.spp);
    for (const LensAt& l : lenses) sweep(l, base, out);
}
