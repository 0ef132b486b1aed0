// The speed-against-accuracy study: prints the Markdown tables of bench/README.md ("Speed against
// accuracy") and draws the convergence curves and film errors into a PNG.
//   tradeoff_report [--reduced] [plot.png]   (default bench/tradeoff/tradeoff.png in the source tree)
// Per-ray timings come from bench_camera_rays (Google Benchmark). Two threads; the machine is
// shared, so frame times are CPU seconds (setup included), the best of three runs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "FilmErrorStudy.h"
#include "FrameStudy.h"
#include "PanelPlot.h"
#include "cameras/RealisticCamera.h"

using namespace lenslab;
using namespace lenslab::tradeoff;

namespace {

const std::vector<std::string> kModes = {"exact", "thick", "auto"};
constexpr int kTableSpp = 16;
const char* const kConvergenceStop = "f/5.6";

// How much is rendered: the full study, or (--reduced, for a loaded machine: about a quarter of the
// samples) fewer reference samples, two repeats and the ladder up to 16 spp; frames stay the same.
struct Effort {
    std::vector<int> sppLadder = {1, 2, 4, 8, 16, 32, 64};
    int referenceSpp = 256, convergenceReferenceSpp = 1024;
    int repeats = 3;
};
Effort effort;

double pixelMm() { return kFilmWidthMm / kFrameWidth; }

LensAnalysis analysisOf(const LensCase& lens, const StopCase& stop) {
    RealisticParams p = realisticParams(lens.path, stop.fstop, kFocusDistanceMm);
    p.filmDiagonalMm = filmDiagonalMm();
    return RealisticCamera(p, {}, kFrameWidth, kFrameHeight, 0.5).analysis();
}

TimedFrame bestOf(const LensCase& lens, const StopCase& stop, const std::string& mode, int spp) {
    TimedFrame best = renderFrame(lens, stop, mode, kFrameWidth, kFrameHeight, spp);
    for (int i = 1; i < effort.repeats; ++i) {
        TimedFrame f = renderFrame(lens, stop, mode, kFrameWidth, kFrameHeight, spp);
        if (f.seconds() < best.seconds()) best = std::move(f);
    }
    return best;
}

void printFilmErrors() {
    std::printf("\n### Geometric error on the film (against the exact double-precision trace)\n\n");
    std::printf("| lens | stop | field (r mm) | thick: worst ray um (px) | thick: centroid um | thick: direction arcmin | "
                "thick / exact brightness | float: worst ray um |\n|---|---|---|---|---|---|---|---|\n");
    for (const LensCase& lens : lensCases())
        for (const StopCase& stop : stopCases()) {
            const LensAnalysis a = analysisOf(lens, stop);
            const std::vector<FieldError> errors = measureFieldErrors(a);
            for (std::size_t i = 0; i < errors.size(); ++i) {
                const ThickLensFilmError& t = errors[i].thick;
                const std::string field = fieldCases()[i].label + " (" + std::to_string(int(std::lround(t.filmRadius))) + ")";
                if (t.exactRays == 0) {
                    std::printf("| %s | f/%.3g | %s | no exact ray passes (outside the image circle) | | | | |\n",
                                lens.name.c_str(), a.fstop, field.c_str());
                    continue;
                }
                std::printf("| %s | f/%.3g | %s | %.1f (%.2f) | %.1f | %.2f | %.3f | %.2g |\n", lens.name.c_str(), a.fstop,
                            field.c_str(), 1e3 * t.maxErrorMm, t.maxErrorMm / pixelMm(), 1e3 * t.centroidErrorMm,
                            t.directionErrorRad * 180 / M_PI * 60, t.illuminationRatio, 1e3 * errors[i].floatMaxErrorMm);
            }
        }
}

struct CaseFrames {
    std::map<std::string, TimedFrame> frames;  // by mode, at kTableSpp
    std::map<std::string, double> rmse;
};

// Time to reach `target` along a mode's convergence curve (log-log interpolation between ladder
// points); negative when the curve never gets there.
double secondsToReach(const std::vector<double>& rmse, const std::vector<double>& seconds, double target) {
    for (std::size_t i = 0; i < rmse.size(); ++i) {
        if (rmse[i] > target) continue;
        if (i == 0) return seconds[0];
        const double t = (std::log(rmse[i - 1]) - std::log(target)) / (std::log(rmse[i - 1]) - std::log(rmse[i]));
        return std::exp(std::log(seconds[i - 1]) + t * (std::log(seconds[i]) - std::log(seconds[i - 1])));
    }
    return -1;
}

}  // namespace

int main(int argc, char** argv) {
    std::string plotPath = std::string(LENSLAB_SOURCE_DIR) + "/bench/tradeoff/tradeoff.png";
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--reduced") effort = {{1, 2, 4, 8, 16}, 64, 256, 2};
        else plotPath = argv[i];
    }
    std::printf("Film %gx%g mm, frame %dx%d (%.3f mm pixels), focus %.1f m, scene shared-world, 2 threads.\n",
                kFilmWidthMm, kFilmHeightMm, kFrameWidth, kFrameHeight, pixelMm(), kFocusDistanceMm / 1000);
    printFilmErrors();

    std::printf("\n### Whole frames: time and image error (%d spp, best of %d runs; RMSE against exact at %d spp, "
                "%d at %s)\n\n", kTableSpp, effort.repeats, effort.referenceSpp, effort.convergenceReferenceSpp, kConvergenceStop);
    std::printf("| lens | stop | auto: thick lens for | CPU s exact | CPU s thick | CPU s auto | auto / faster | "
                "RMSE exact | RMSE thick | RMSE auto |\n|---|---|---|---|---|---|---|---|---|---|\n");
    std::map<std::string, Image> convergenceReference;
    for (const LensCase& lens : lensCases())
        for (const StopCase& stop : stopCases()) {
            const bool convergenceStop = stop.label == kConvergenceStop;
            const Image reference = renderFrame(lens, stop, "exact", kFrameWidth, kFrameHeight,
                                                convergenceStop ? effort.convergenceReferenceSpp : effort.referenceSpp).image;
            if (convergenceStop) convergenceReference[lens.name] = reference;
            CaseFrames c;
            for (const std::string& mode : kModes) {
                c.frames[mode] = bestOf(lens, stop, mode, kTableSpp);
                c.rmse[mode] = relativeRmse(c.frames[mode].image, reference);
            }
            const double faster = std::min(c.frames["exact"].seconds(), c.frames["thick"].seconds());
            std::printf("| %s | %s | %s | %.3f | %.3f | %.3f | %.2f | %.4f | %.4f | %.4f |\n", lens.name.c_str(),
                        stop.label.c_str(), c.frames["auto"].split.c_str(), c.frames["exact"].seconds(),
                        c.frames["thick"].seconds(), c.frames["auto"].seconds(), c.frames["auto"].seconds() / faster,
                        c.rmse["exact"], c.rmse["thick"], c.rmse["auto"]);
            std::fflush(stdout);
        }

    std::printf("\n### Convergence at %s: relative RMSE against exact at %d spp (CPU seconds per frame in brackets)\n\n",
                kConvergenceStop, effort.convergenceReferenceSpp);
    std::printf("| lens | mode |");
    for (int spp : effort.sppLadder) std::printf(" %d spp |", spp);
    std::printf("\n|---|---|");
    for (std::size_t i = 0; i < effort.sppLadder.size(); ++i) std::printf("---|");
    std::printf("\n");
    std::vector<Panel> panels;
    Panel trade{"CPU seconds per frame against error, " + lensCases().front().name, "CPU seconds per frame", "relative RMSE",
                true, true, {}};
    std::vector<std::string> reach;
    for (const LensCase& lens : lensCases()) {
        const StopCase stop{5.6, kConvergenceStop};
        Panel panel{lens.name + " at " + kConvergenceStop, "samples per pixel", "relative RMSE", true, true, {}};
        std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> curves;  // rmse, seconds
        for (const std::string& mode : kModes) {
            Series s{mode, {}, {}, mode == "auto"};
            std::printf("| %s | %s |", lens.name.c_str(), mode.c_str());
            for (int spp : effort.sppLadder) {
                const TimedFrame f = bestOf(lens, stop, mode, spp);
                const double e = relativeRmse(f.image, convergenceReference[lens.name]);
                s.x.push_back(spp);
                s.y.push_back(e);
                curves[mode].first.push_back(e);
                curves[mode].second.push_back(f.seconds());
                std::printf(" %.4f (%.2f) |", e, f.seconds());
            }
            std::printf("\n");
            std::fflush(stdout);
            if (lens.name == lensCases().front().name)
                trade.series.push_back({mode, curves[mode].second, curves[mode].first, mode == "auto"});
            panel.series.push_back(std::move(s));
        }
        panels.push_back(std::move(panel));
        // Auto against the faster mode, at the error exact reaches with kTableSpp samples.
        const double target = curves["exact"].first[std::find(effort.sppLadder.begin(), effort.sppLadder.end(), kTableSpp) -
                                                       effort.sppLadder.begin()];
        char line[512];
        const auto when = [&](const std::string& mode) {
            const double s = secondsToReach(curves[mode].first, curves[mode].second, target);
            char b[64];
            if (s < 0) std::snprintf(b, sizeof b, "never (floor %.4f)", curves[mode].first.back());
            else std::snprintf(b, sizeof b, "%.3f", s);
            return std::string(b);
        };
        std::snprintf(line, sizeof line, "| %s | %.4f | %s | %s | %s |", lens.name.c_str(), target, when("exact").c_str(),
                      when("thick").c_str(), when("auto").c_str());
        reach.push_back(line);
    }
    std::printf("\n### CPU seconds per frame to reach exact's %d-spp error (%s; interpolated along the curves above)\n\n",
                kTableSpp, kConvergenceStop);
    std::printf("| lens | target RMSE | exact CPU s | thick CPU s | auto CPU s |\n|---|---|---|---|---|\n");
    for (const std::string& l : reach) std::printf("%s\n", l.c_str());

    Panel film{"thick-lens film error at " + std::string(kConvergenceStop), "field position (film radius, mm)",
               "worst ray error (pixels)", false, true, {}};
    for (const LensCase& lens : lensCases()) {
        Series s{lens.name, {}, {}, false};
        for (const FieldError& e : measureFieldErrors(analysisOf(lens, {5.6, kConvergenceStop}))) {
            s.x.push_back(e.thick.filmRadius);
            s.y.push_back(e.thick.exactRays > 0 ? e.thick.maxErrorMm / pixelMm() : NAN);
        }
        film.series.push_back(std::move(s));
    }
    film.series.push_back({"half a pixel (auto's threshold)", {0, filmHalfDiagonalMm()}, {0.5, 0.5}, true});
    panels.push_back(std::move(film));
    panels.push_back(std::move(trade));
    const std::vector<unsigned char> png = drawPanelsPng(panels, 3, 560, 400);
    std::ofstream(plotPath, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    std::printf("\nPlot: %s\n", plotPath.c_str());
    return 0;
}
