// `lenslab render`: renders a scene to one or more images, with a progress bar and ETA on stderr.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ArgParser.h"
#include "Commands.h"
#include "LensFlags.h"
#include "MpiRender.h"
#include "Render.h"

namespace lenslab {

namespace {

// N comma-separated numbers, e.g. --crop x0,x1,y0,y1.
template <std::size_t N>
std::array<double, N> parseNumbers(const std::string& text, const char* flag, const char* what) {
    std::array<double, N> c{};
    std::istringstream in(text);
    std::string part;
    for (std::size_t i = 0; i < N; ++i) {
        if (!std::getline(in, part, ',')) throw UsageError(std::string("render: ") + flag + " needs " + what);
        try {
            std::size_t used = 0;
            c[i] = std::stod(part, &used);
            if (used != part.size()) throw std::invalid_argument(part);
        } catch (const std::exception&) {
            throw UsageError(std::string("render: ") + flag + ": '" + part + "' is not a number");
        }
    }
    if (std::getline(in, part, ',')) throw UsageError(std::string("render: ") + flag + " takes exactly " + std::to_string(N) + " numbers");
    return c;
}

// Redraws one terminal line: a bar, the tile count and the time left at the current rate.
class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}
    void update(int done, int total) {
        if (!enabled_) return;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double eta = done > 0 ? elapsed * (total - done) / done : 0.0;
        constexpr int kWidth = 40;
        const int filled = total > 0 ? kWidth * done / total : kWidth;
        std::fprintf(stderr, "\r[%s%s] %d/%d tiles  %.1fs  ETA %.1fs ", std::string(filled, '#').c_str(),
                     std::string(kWidth - filled, '.').c_str(), done, total, elapsed, eta);
        if (done == total) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
};

// --progress-json: one line per finished tile on stdout, for programs driving the render (the
// server's MPI jobs); a last line {"finished":true,...} carries the statistics once the images are written.
void printProgressJson(const TileUpdate& u) {
    std::printf("{\"tilesDone\":%d,\"tilesTotal\":%d,\"x0\":%d,\"y0\":%d,\"x1\":%d,\"y1\":%d}\n", u.tilesDone,
                u.tilesTotal, u.x0, u.y0, u.x1, u.y1);
    std::fflush(stdout);
}

// "loading scene  42%" on stderr once a scene has taken half a second to read: redrawn in place on
// a terminal, a line per quarter otherwise.
class SceneLoadProgress {
public:
    explicit SceneLoadProgress(bool terminal) : terminal_(terminal) {}
    void operator()(double fraction) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (elapsed < 0.5) return;
        const int percent = int(fraction * 100);
        const int step = terminal_ ? 1 : 25;
        if (percent / step == shown_ / step && percent != 100) return;
        if (percent == shown_) return;
        shown_ = percent;
        std::fprintf(stderr, terminal_ ? "\rloading scene %3d%%%s" : "loading scene %3d%%\n%s", percent,
                     terminal_ && percent == 100 ? "\n" : "");
    }

private:
    bool terminal_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    int shown_ = -1;
};

// -o may repeat: every occurrence is taken out before the parser (which keeps one value per
// option); the rest are returned.
std::vector<std::string> takeOutputs(const std::vector<std::string>& argsIn, std::vector<std::string>& outputs) {
    std::vector<std::string> args;
    for (std::size_t i = 0; i < argsIn.size(); ++i) {
        const std::string& a = argsIn[i];
        if (a == "-o" || a == "--output") {
            if (i + 1 >= argsIn.size()) throw UsageError("render: -o needs a file name");
            outputs.push_back(argsIn[++i]);
        } else if (a.rfind("-o=", 0) == 0) {
            outputs.push_back(a.substr(3));
        } else {
            args.push_back(a);
        }
    }
    for (const auto& o : outputs) {
        const std::string ext = imageFileExtension(o);
        if (ext != ".exr" && ext != ".png" && ext != ".dng")
            throw UsageError("render: output '" + o + "' must end in .exr, .png or .dng");
    }
    return args;
}

// A raw file holds a mosaic's numbers: refused before the render when the sensor has none.
void checkRawOutputs(const std::vector<std::string>& outputs, const RenderSettings& s) {
    for (const auto& o : outputs)
        if (imageFileExtension(o) == ".dng" && !(s.sensor && s.sensor->colourFilter))
            throw UsageError("render: output '" + o + "' is a raw DNG file: it needs a sensor with a colour mosaic "
                             "(--sensor ...,cfa=rggb, bggr, grbg or gbrg)");
}

RenderSettings renderSettings(const ArgParser& p) {
    RenderSettings s;
    s.scenePath = p.arg(0);
    if (auto v = p.integer("--spp")) s.spp = int(*v);
    if (auto v = p.integer("--threads")) s.threads = int(*v);
    if (auto v = p.integer("--tile")) s.tileSize = int(*v);
    if (auto v = p.integer("--width")) s.width = int(*v);
    if (auto v = p.integer("--height")) s.height = int(*v);
    if (auto v = p.integer("--seed")) s.seed = std::uint64_t(*v);
    if (p.has("--crop")) s.crop = parseNumbers<4>(p.get("--crop"), "--crop", "x0,x1,y0,y1 (fractions of the image)");
    if (p.has("--lens")) s.camera.lensFile = p.get("--lens");
    if (p.has("--layout")) {
        s.camera.lensLayout = parseLayoutName(p.get("--layout"));
        if (!s.camera.lensLayout) throw UsageError("render: --layout must be gap-before or gap-after, got '" + p.get("--layout") + "'");
    }
    const LensSettings flags = lensFlags(p);
    s.camera.fstop = flags.fstop;
    s.camera.focusDistance = flags.focusDistance;
    s.camera.wavelength = flags.wavelength;
    if (auto v = p.number("--filmdiag")) s.camera.filmDiagonal = *v;
    if (p.has("--mode")) s.camera.mode = p.get("--mode");
    s.camera.tiltDegrees = p.number("--tilt");
    s.camera.swingDegrees = p.number("--swing");
    if (p.has("--shift")) s.camera.shiftMm = parseNumbers<2>(p.get("--shift"), "--shift", "x,y (millimetres)");
    if (p.has("--spectral")) {
        const std::string v = p.get("--spectral");
        if (v != "on" && v != "off") throw UsageError("render: --spectral must be on or off, got '" + v + "'");
        s.camera.spectral = v == "on";
    }
    if (p.has("--ghosts")) s.camera.ghosts = p.get("--ghosts");
    if (p.has("--ghost-model")) s.camera.ghostModel = p.get("--ghost-model");
    if (auto v = p.integer("--wavelengths-per-sample")) s.wavelengthsPerSample = int(*v);
    if (p.has("--sensor")) {
        try {
            s.sensor = sensorSpecFromPairs(parseSensorPairs(p.get("--sensor")));
        } catch (const SensorSpecError& e) {
            throw UsageError(std::string("render --") + e.what());
        }
    }
    return s;
}

// The closing lines: the JSON statistics (and the render's warnings) for --progress-json, the human
// summary otherwise.
void printStatistics(const RenderOutput& out, bool json, bool quiet, const std::vector<std::string>& outputs) {
    const RenderStats& st = out.stats;
    if (json) {
        const nlohmann::json finished = {{"finished", true},           {"setupSeconds", st.setupSeconds},
                                         {"renderSeconds", st.renderSeconds}, {"cameraRays", st.cameraRays},
                                         {"blockedCameraRays", st.blockedCameraRays}, {"raysTraced", st.raysTraced},
                                         {"flarePaths", st.flarePaths}, {"flareRays", st.flareRays},
                                         {"flareSeconds", st.flareSeconds}, {"warnings", out.warnings}};
        std::printf("%s\n", finished.dump().c_str());
        std::fflush(stdout);
    }
    if (quiet) return;
    const double blocked = st.cameraRays ? double(st.blockedCameraRays) / st.cameraRays : 0.0;
    std::fprintf(stderr, "setup %.3f s, render %.3f s, %.2f Mrays/s, %.2f%% of camera rays blocked by the lens\n",
                 st.setupSeconds, st.renderSeconds, st.raysTraced / std::max(st.renderSeconds, 1e-9) * 1e-6, 100.0 * blocked);
    if (st.flarePaths > 0)
        std::fprintf(stderr, "lens flare: %d ghost paths of %d emitters, %.2f Mrays, %.3f s (in the setup)\n", st.flarePaths,
                     st.flareSources, st.flareRays * 1e-6, st.flareSeconds);
    for (const auto& o : outputs) std::fprintf(stderr, "wrote %s\n", o.c_str());
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& argsIn) {
    ArgParser p("render", "SCENE [-o out.exr] [-o out.png] [--spp N] [--threads N] [--tile N] [--crop x0,x1,y0,y1]",
                "Renders a pbrt-v3 scene (lenslab's subset; world in metres, lens in millimetres) with the\n"
                "perspective or the realistic lens camera. Output by extension: .exr (linear float RGB, tiled,\n"
                "camera and lens parameters in the header), .png (sRGB, scaled by --exposure) or .dng (a colour\n"
                "mosaic sensor's raw numbers).");
    p.positional("SCENE", "scene file (.pbrt)");
    p.option("-o", "FILE", "output image, .exr, .png or .dng; repeat for several (default: the scene's Film filename)");
    p.option("--spp", "N", "samples per pixel (default: the scene's)");
    p.option("--threads", "N", "worker threads (default: all cores)");
    p.option("--tile", "N", "tile size in pixels (default 32)");
    p.option("--crop", "X0,X1,Y0,Y1", "render only this window (fractions of the image)");
    p.option("--width", "N", "image width (default: the scene's)");
    p.option("--height", "N", "image height (default: the scene's)");
    p.option("--seed", "N", "random seed (default 0)");
    p.option("--exposure", "E", "PNG exposure scale (default 1)");
    p.option("--lens", "FILE", "realistic camera: lens table or .zmx prescription instead of the scene's specfile");
    p.option("--spectral", "on|off", "wavelengths per sample through the lens's dispersion, the film through the CIE "
             "matching functions (default: on when the lens disperses and no --wavelength is given)");
    p.option("--wavelengths-per-sample", "N", "spectral: wavelengths each camera sample carries, 1 to 8 (default 3, 1 with the box filter)");
    declareLensFlags(p);
    p.option("--filmdiag", "MM", "realistic camera: film diagonal, mm");
    p.option("--tilt", "DEG", "realistic camera: tilt the lens about the film's horizontal axis (positive: its axis down; Scheimpflug)");
    p.option("--swing", "DEG", "realistic camera: swing the lens about the film's vertical axis (positive: its axis right)");
    p.option("--shift", "X,Y", "realistic camera: shift the lens across the film, mm (positive y: rising front)");
    p.option("--layout", "L", "realistic camera: the --lens table's layout, gap-before | gap-after (default: detect)");
    p.option("--mode", "M", "realistic camera: exact | thick | auto (thick lens where its position error < 0.5 px and brightness within 3%, over 90%+ of the film; else exact)");
    p.option("--ghosts", "G", "realistic camera: lens flare, off | auto (only with an emitter bright enough in or near the frame) |\n"
             "all | N (the N brightest ghosts of the ghost analysis); default off");
    p.option("--ghost-model", "M", "with --ghosts: exact (every ghost traced through the coated lens) | paraxial (its\n"
             "ray-transfer matrices: the stop's shape, uniform); default exact");
    p.option("--sensor", "K=V,...", "realistic camera: a real sensor's noisy readout instead of the noiseless film (docs/sensor.md):\n"
             "iso exposure(s; default metered) gain(e-/DN) qe fill pitch(um) fullwell(e-) read(e-) dark(e-/s) dsnu prnu\n"
             "bits black(DN) nits(cd/m^2 per unit radiance) pattern(seed) cfa(none|rggb|bggr|grbg|gbrg: a Bayer mosaic,\n"
             "demosaiced; -o raw.dng writes its raw numbers); e.g. --sensor iso=3200,exposure=0.004,cfa=rggb");
    p.flag("--quiet", "no progress bar, no summary");
    p.flag("--progress-json", "print one JSON line per finished tile on stdout, and the statistics last");
    p.flag("--mpi", "spread the tiles over the processes of an MPI job: mpirun -np N lenslab render ... --mpi");
    p.option("--mpi-timeout", "S", "with --mpi: a worker silent this long is taken as dead and its tile re-queued (default 10)");

    std::vector<std::string> outputs;
    if (!p.parse(takeOutputs(argsIn, outputs))) {
        std::cout << p.help();
        return 0;
    }
    RenderSettings s = renderSettings(p);
    checkRawOutputs(outputs, s);
    const double exposure = p.number("--exposure").value_or(1.0);
    if (!(exposure > 0)) throw UsageError("render: --exposure must be positive");
    const bool quiet = p.has("--quiet");

    if (!quiet) s.loadProgress = SceneLoadProgress(::isatty(STDERR_FILENO));
    const bool progressJson = p.has("--progress-json");
    ProgressBar bar(!quiet && ::isatty(STDERR_FILENO));
    const auto onTile = [&](const TileUpdate& u, const Image&) {
        bar.update(u.tilesDone, u.tilesTotal);
        if (progressJson) printProgressJson(u);
    };
    std::optional<RenderOutput> rendered;
    if (p.has("--mpi")) {
        MpiRenderOptions mpi;
        if (auto v = p.number("--mpi-timeout")) mpi.workerTimeoutSeconds = *v;
        if (!(mpi.workerTimeoutSeconds > 0)) throw UsageError("render: --mpi-timeout must be positive");
        rendered = renderSceneOverMpi(s, mpi, onTile);
        if (!rendered) return 0;  // an MPI worker: rank 0 writes the image
    } else {
        rendered = renderScene(s, onTile);
    }
    const RenderOutput& out = *rendered;
    if (outputs.empty()) {
        auto it = out.metadata.find("filmFilename");
        outputs.push_back(it != out.metadata.end() ? it->second : "lenslab.exr");
    }
    for (const auto& o : outputs) writeImageFile(out, o, exposure);
    if (auto it = out.metadata.find("warnings"); it != out.metadata.end()) std::cerr << "warnings:\n" << it->second << "\n";
    for (const std::string& w : out.warnings) std::cerr << "warning: " << w << "\n";
    printStatistics(out, progressJson, quiet, outputs);
    return 0;
}

}  // namespace lenslab
